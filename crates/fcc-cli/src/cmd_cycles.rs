//! `fcc cycles`: Verilator cycle counts per K on the synthetic corpus and on
//! the real Ouster frames, every frame checked against the golden model.
//!
//! Writes the JSON array that `fcc synth --all --cycles-json` attaches to the
//! results report: `{fsize, corpus, frames, pixels, cycles_per_frame,
//! max_cycles_per_frame, latency_cycles}` per K and corpus.

use anyhow::Context;
use clap::Args;
use fcc_golden::Frame;
use fcc_lidar::ground::{detect_ground, GroundParams};
use fcc_lidar::ouster::{read_capture, sample_dir, DecodeOptions, OusterMetadata, SAMPLE_CAPTURES};
use fcc_params::{FccParams, Scan};
use fcc_scene::{generate, SceneConfig};
use fcc_sim::column::{quantile, ColDrive, ColFrame};
use fcc_sim::{load, run_and_check, Drive, Dut};
use fcc_synth::results::{CycleInput, StreamCycles, SYNTHETIC_CORPUS};
use std::path::{Path, PathBuf};

#[derive(Args, Debug, Clone)]
pub struct CyclesArgs {
    /// Filter sizes to measure.
    #[arg(long, num_args = 1.., value_delimiter = ',', allow_negative_numbers = true, default_values_t = [3usize, 5, 7, 9, 11])]
    pub fsize: Vec<usize>,
    /// Synthetic 64 x 2048 scenes per K (seeds 1..=N).
    #[arg(long, default_value_t = 4)]
    pub frames: u64,
    /// Directory holding the Ouster sample captures and their metadata
    /// (default: fcc-lidar's tests/data in the source tree `fcc` was built
    /// from; an empty string skips them).
    #[arg(long, value_parser = clap::builder::TypedValueParser::map(clap::builder::OsStringValueParser::new(), PathBuf::from))]
    pub ouster_dir: Option<PathBuf>,
    /// Write the measurements here as JSON.
    #[arg(long)]
    pub json: Option<PathBuf>,
    /// The core: `row` (default) or `column` (the column-streaming core:
    /// each corpus's frames back to back, record latency reported).
    #[arg(long, default_value = "row")]
    pub scan: Scan,
    /// Label width of the column core's builds (its default: enough for
    /// the corpus, whose most labels in use at once this reports).
    #[arg(long, default_value_t = Scan::Column.default_label_bits())]
    pub label_bits: u32,
    /// The column core's bridge limit (default: the recommended streaming
    /// setting; 0xFFF or more: none).
    #[arg(long, default_value_t = fcc_params::RECOMMENDED_BRIDGE)]
    pub bridge: u32,
    /// The column core's ring reach (default: the recommended streaming
    /// setting; 0xFFF or more: none).
    #[arg(long, default_value_t = fcc_params::RECOMMENDED_RING_REACH)]
    pub ring_reach: u32,
}

/// Run `frames` back to back through the column core of `p`, checking every
/// record; one measurement.
fn measure_columns(p: &FccParams, corpus: &str, frames: &[Frame]) -> anyhow::Result<StreamCycles> {
    let mut dut = Dut::new(load(p)?);
    dut.reset(4);
    let set = frames
        .iter()
        .enumerate()
        .map(|(i, f)| ColFrame::new(p, f, fcc_sim::Tlast::Normal, &format!("{corpus} frame {i}")))
        .collect::<Result<Vec<_>, _>>()?;
    let run = dut
        .run_columns(&set, &ColDrive::default())
        .with_context(|| format!("K = {}, {corpus}", p.fsize))?;
    let q = |v: &[u64], x: f64| quantile(v, x);
    Ok(StreamCycles {
        fsize: p.fsize,
        corpus: corpus.to_string(),
        frames: frames.len(),
        rows: p.rows,
        pixels: p.pixels(),
        label_bits: p.label_bits,
        cycles_per_pixel: run.cycles_per_pixel(&set, p),
        records: run.latency.len(),
        latency_median: q(&run.latency, 0.5),
        latency_99: q(&run.latency, 0.99),
        latency_max: q(&run.latency, 1.0),
        end_records: run.end_latency.len(),
        end_latency_max: q(&run.end_latency, 1.0),
        labels_in_use_max: run.status.iter().map(|s| s.1).max().unwrap_or(0),
        held_cycles: run.status.iter().map(|s| u64::from(s.2)).sum(),
    })
}

/// Run `frames` through the core of `p`, checking each; returns one measurement.
fn measure(p: &FccParams, corpus: &str, frames: &[Frame]) -> anyhow::Result<CycleInput> {
    let mut dut = Dut::new(load(p)?);
    dut.reset(4);
    let (mut sum, mut max, mut lat) = (0.0, 0.0f64, 0.0);
    for (i, f) in frames.iter().enumerate() {
        let run = run_and_check(
            &mut dut,
            f,
            &Drive::default(),
            &format!("{corpus} frame {i}"),
        )?;
        sum += run.cycles as f64;
        max = max.max(run.cycles as f64);
        lat += run.latency as f64;
    }
    let n = frames.len() as f64;
    Ok(CycleInput {
        fsize: p.fsize,
        corpus: corpus.to_string(),
        frames: frames.len() as u64,
        pixels: Some(p.pixels()),
        cycles_per_frame: sum / n,
        max_cycles_per_frame: max,
        latency_cycles: lat / n,
    })
}

/// The Ouster frames of `dir`, each with its ground left in and removed.
fn ouster_frames(dir: &Path) -> anyhow::Result<Vec<(String, Frame, Frame)>> {
    let mut out = Vec::new();
    for (pcap, json) in SAMPLE_CAPTURES {
        let meta = OusterMetadata::from_file(&dir.join(json))?;
        let cap = read_capture(&dir.join(pcap), &meta, DecodeOptions::default())?;
        for fr in cap.frames {
            let img = fr.image;
            let ground = detect_ground(&img, &GroundParams::default())?;
            let name = pcap.split('_').next().unwrap_or(pcap).to_string();
            out.push((
                format!("{name} {}x{}", img.rows, img.cols),
                img.to_frame(),
                img.without(&ground.mask).to_frame(),
            ));
        }
    }
    Ok(out)
}

/// The corpus: the synthetic scenes (64 x 2048) and the Ouster frames
/// (each with its ground removed and kept).
type Corpus = (Vec<Frame>, Vec<(String, Frame, Frame)>);

fn corpus(args: &CyclesArgs, base: &FccParams) -> anyhow::Result<Corpus> {
    let scenes = (1..=args.frames)
        .map(|seed| {
            let cfg = SceneConfig {
                rows: base.rows,
                cols: base.cols,
                seed,
                ..SceneConfig::default()
            };
            let s = generate(&cfg)?;
            Ok(Frame::from_xyz_f32(s.rows, s.cols, &s.xyz))
        })
        .collect::<anyhow::Result<Vec<_>>>()?;
    let dir = args.ouster_dir.clone().unwrap_or_else(sample_dir);
    let ouster = if dir.as_os_str().is_empty() {
        Vec::new()
    } else {
        ouster_frames(&dir).with_context(|| {
            format!(
                "Ouster sample captures in {} (pass --ouster-dir DIR, or --ouster-dir '' to skip them)",
                dir.display()
            )
        })?
    };
    Ok((scenes, ouster))
}

/// `measure` of every K asked for on the corpus (the scenes together, each
/// capture with its ground removed and kept), cores built from `base`,
/// with progress on stderr.
fn each_build<T>(
    args: &CyclesArgs,
    base: &FccParams,
    measure: impl Fn(&FccParams, &str, &[Frame]) -> anyhow::Result<T>,
) -> anyhow::Result<Vec<T>> {
    let (scenes, ouster) = corpus(args, base)?;
    let mut all = Vec::new();
    for &k in &args.fsize {
        let p = FccParams {
            fsize: k,
            ..base.clone()
        };
        p.validate_for_hardware()?;
        eprintln!("K = {k}: {} synthetic scenes ...", scenes.len());
        all.push(measure(&p, SYNTHETIC_CORPUS, &scenes)?);
        for (name, with_ground, without) in &ouster {
            let q = FccParams {
                rows: with_ground.rows,
                cols: with_ground.cols,
                ..p.clone()
            };
            eprintln!("K = {k}: {name} ...");
            all.push(measure(
                &q,
                &format!("{name} ground removed"),
                std::slice::from_ref(without),
            )?);
            all.push(measure(
                &q,
                &format!("{name} ground kept"),
                std::slice::from_ref(with_ground),
            )?);
        }
    }
    Ok(all)
}

/// All measurements asked for, with progress on stderr.
pub fn collect(args: &CyclesArgs) -> anyhow::Result<Vec<CycleInput>> {
    each_build(args, &FccParams::default(), measure)
}

/// The column core's measurements (each corpus's frames back to back),
/// with progress on stderr.
pub fn collect_columns(args: &CyclesArgs) -> anyhow::Result<Vec<StreamCycles>> {
    let none = |v: u32| (v < fcc_rtl::regmap::LIMIT_MAX).then_some(v);
    let base = FccParams {
        label_bits: args.label_bits,
        bridge: none(args.bridge),
        ring_reach: none(args.ring_reach),
        scan: Scan::Column,
        ..FccParams::default()
    };
    each_build(args, &base, measure_columns)
}

fn run_columns(args: &CyclesArgs) -> anyhow::Result<()> {
    let all = collect_columns(args)?;
    println!("| K | corpus | frames | cycles / pixel | records | latency median / 99 % / max | R | frame-end records, max latency | labels in use, most | column starts held |");
    println!("|---|---|---|---|---|---|---|---|---|---|");
    for m in &all {
        println!(
            "| {} | {} | {} | {:.3} | {} | {} / {} / {} | {} | {}, {} | {} | {} |",
            m.fsize,
            m.corpus,
            m.frames,
            m.cycles_per_pixel,
            m.records,
            m.latency_median,
            m.latency_99,
            m.latency_max,
            m.rows,
            m.end_records,
            m.end_latency_max,
            m.labels_in_use_max,
            m.held_cycles
        );
    }
    if let Some(path) = &args.json {
        fcc_io::write_atomic(path, serde_json::to_string_pretty(&all)?.as_bytes())
            .with_context(|| format!("{}: cannot write", path.display()))?;
    }
    Ok(())
}

pub fn run(args: &CyclesArgs) -> anyhow::Result<()> {
    if args.scan == Scan::Column {
        return run_columns(args);
    }
    let all = collect(args)?;
    println!("| K | corpus | frames | cycles / frame | x R x C | latency |");
    println!("|---|---|---|---|---|---|");
    for m in &all {
        let px = m.pixels.unwrap_or(1) as f64;
        println!(
            "| {} | {} | {} | {:.0} | {:.3} | {:.0} |",
            m.fsize,
            m.corpus,
            m.frames,
            m.cycles_per_frame,
            m.cycles_per_frame / px,
            m.latency_cycles
        );
    }
    if let Some(path) = &args.json {
        fcc_io::write_atomic(path, serde_json::to_string_pretty(&all)?.as_bytes())
            .with_context(|| format!("{}: cannot write", path.display()))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::Parser;

    #[derive(Parser)]
    struct Cli {
        #[command(flatten)]
        cycles: CyclesArgs,
    }

    #[test]
    fn an_empty_ouster_dir_skips_the_captures() {
        let a = Cli::try_parse_from(["cycles", "--ouster-dir", "", "--frames", "0"])
            .expect("`--ouster-dir ''` is how the captures are skipped")
            .cycles;
        assert_eq!(a.ouster_dir, Some(PathBuf::new()));
        let (scenes, ouster) = corpus(&a, &FccParams::default()).unwrap();
        assert!(scenes.is_empty() && ouster.is_empty());
    }
}
