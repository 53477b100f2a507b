//! `fcc`: Fast Channel Clustering of LiDAR range images.
//!
//! Every subcommand builds one validated [`fcc_params::FccParams`] from its
//! arguments and hands it to the library crates. Errors end the program with
//! one line on stderr and exit code 2.

use clap::{Parser, Subcommand};

mod cmd_bench;
mod cmd_board;
mod cmd_cycles;
mod cmd_gen;
mod cmd_lidar;
mod cmd_live;
mod cmd_results;
mod cmd_scene;
mod cmd_sim;
mod cmd_stream;
mod cmd_synth;
mod model_args;
mod progress;
mod sensor_args;
mod slot_load;

#[derive(Parser)]
#[command(
    name = "fcc",
    version,
    about = "Fast Channel Clustering of LiDAR range images: golden model, tools and RTL generator"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Cluster LiDAR frames with the golden model: Ouster and Velodyne captures,
    /// ROS 2 recordings (.mcap), KITTI .bin, PCD, PLY or .npy range images in;
    /// labels, cluster tables, pictures and statistics out.
    Cluster(cmd_lidar::ClusterLidarArgs),
    /// Cluster a live sensor: Ouster or Velodyne UDP packets in, one JSON
    /// line per record out (as `cluster --stream`).
    ///
    /// With `--ground none` the column path runs: the frame's columns go
    /// through the stream and each record is written as it closes. Ground
    /// removal `slope` (the default) and `plane` fit a plane to the whole
    /// frame, so they run the frame path: a frame's records are written
    /// after its ground removal. Stderr names the path. Live gives the
    /// records of `cluster --stream` exactly. With the sensor's image (the
    /// default `--image-origin sensor`) and for Velodyne, clustering starts
    /// on the frame's last packet: the image's first columns need the whole
    /// frame. With `--ground none --image-origin sweep` (Ouster) each column
    /// goes into the stream with the packet that completes it, and frames
    /// that miss columns are kept, as `--keep-incomplete`.
    Live(cmd_live::LiveArgs),
    /// Send a capture's UDP packets to a socket at their recorded timing.
    Replay(cmd_live::ReplayArgs),
    /// Convert captures and point clouds to .npy range images (R, C, 3).
    Convert(cmd_lidar::ConvertArgs),
    /// Clustering quality (PQ, SQ, RQ, over/under-segmentation) per K and merge mode.
    Eval(cmd_lidar::EvalArgs),
    /// Make a synthetic LiDAR scene with ground truth.
    Scene(cmd_scene::SceneArgs),
    /// Generate the RTL (Verilog, XDC, Vivado Tcl) for one configuration.
    Gen(cmd_gen::GenArgs),
    /// Run one frame through the generated RTL in Verilator and compare with the golden model.
    Sim(cmd_sim::SimArgs),
    /// Resource and pre-route timing estimate of the generated RTL (Yosys), or the
    /// Vivado build when `vivado` is on PATH; `--all` writes docs/results.md.
    Synth(cmd_synth::SynthArgs),
    /// Verilator cycles per frame per K on the synthetic corpus and the real Ouster frames.
    Cycles(cmd_cycles::CyclesArgs),
    /// Regenerate docs/results.md and its JSON: bench, cycles and synth for every K.
    Results(cmd_results::ResultsArgs),
    /// How soon the golden stream closes its records, per K and reach
    /// setting, on the synthetic corpus and Ouster captures (docs/streaming.md).
    StreamReport(cmd_stream::StreamReportArgs),
    /// Time the golden model per K on synthetic scenes; compare exact and paper merging.
    Bench(cmd_bench::BenchArgs),
    /// Drive the core on a board (Linux UIO) or on the virtual board (Verilator
    /// with a model of the AXI DMA), checking every label against the golden model.
    #[command(subcommand)]
    Board(cmd_board::BoardCommand),
}

fn main() {
    let cli = Cli::parse();
    let result = match &cli.command {
        Command::Cluster(a) => cmd_lidar::run_cluster(a),
        Command::Live(a) => cmd_live::run_live(a),
        Command::Replay(a) => cmd_live::run_replay(a),
        Command::Convert(a) => cmd_lidar::run_convert(a),
        Command::Eval(a) => cmd_lidar::run_eval(a),
        Command::Scene(a) => cmd_scene::run(a),
        Command::Bench(a) => cmd_bench::run(a),
        Command::StreamReport(a) => cmd_stream::run(a),
        Command::Cycles(a) => cmd_cycles::run(a),
        Command::Results(a) => cmd_results::run(a),
        Command::Gen(a) => cmd_gen::run(a),
        Command::Sim(a) => cmd_sim::run(a),
        Command::Synth(a) => cmd_synth::run(a),
        Command::Board(a) => cmd_board::run(a),
    };
    if let Err(e) = result {
        eprintln!("error: {}", error_line(&e));
        std::process::exit(2);
    }
}

/// An error and its causes on one line, each cause once: a cause whose text
/// an outer message already quotes (an OS error inside "path: cannot write:
/// ...") is not repeated. Details a message carries on further lines (a
/// tool's log tail) follow the first line.
fn error_line(e: &anyhow::Error) -> String {
    let mut line = String::new();
    for cause in e.chain() {
        let text = cause.to_string();
        if line.contains(text.trim()) {
            continue;
        }
        if !line.is_empty() {
            line.push_str(": ");
        }
        line.push_str(text.trim());
    }
    line
}
