//! `fcc`: Fast Channel Clustering of LiDAR range images.
//!
//! Every subcommand builds one validated [`fcc_params::FccParams`] from its
//! arguments and hands it to the library crates. Errors end the program with
//! one line on stderr and exit code 2.

use clap::{Parser, Subcommand};

mod cmd_bench;
mod cmd_cluster;
mod cmd_scene;
mod model_args;

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
    /// Cluster range images (.npy, shape (R, C, 3)) with the golden model.
    Cluster(cmd_cluster::ClusterArgs),
    /// Make a synthetic LiDAR scene with ground truth.
    Scene(cmd_scene::SceneArgs),
    /// Time the golden model per K on synthetic scenes; compare exact and paper merging.
    Bench(cmd_bench::BenchArgs),
}

fn main() {
    let cli = Cli::parse();
    let result = match &cli.command {
        Command::Cluster(a) => cmd_cluster::run(a),
        Command::Scene(a) => cmd_scene::run(a),
        Command::Bench(a) => cmd_bench::run(a),
    };
    if let Err(e) = result {
        eprintln!("error: {e:#}");
        std::process::exit(2);
    }
}
