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
use fcc_params::FccParams;
use fcc_scene::{generate, SceneConfig};
use fcc_sim::{load, run_and_check, Drive, Dut};
use fcc_synth::results::{CycleInput, SYNTHETIC_CORPUS};
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
    #[arg(long)]
    pub ouster_dir: Option<PathBuf>,
    /// Write the measurements here as JSON.
    #[arg(long)]
    pub json: Option<PathBuf>,
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

/// All measurements asked for, with progress on stderr.
pub fn collect(args: &CyclesArgs) -> anyhow::Result<Vec<CycleInput>> {
    let base = FccParams::default();
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

pub fn run(args: &CyclesArgs) -> anyhow::Result<()> {
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
