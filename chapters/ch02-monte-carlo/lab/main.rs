//! `ch02-monte-carlo`: the chapter's figures, and warped samples as CSV.

use anyhow::Context;
use ch02_monte_carlo::lab::figures;
use ch02_monte_carlo::samples::samples_csv;
use ch02_monte_carlo::warps::Warp;
use clap::{Parser, Subcommand};
use std::path::PathBuf;
use std::process::ExitCode;
use workbench::cli::{FiguresArgs, check_writable, report_error};

/// Chapter 02 of the workbook: Monte Carlo integration and stochastic sampling.
#[derive(Parser, Debug)]
#[command(name = "ch02-monte-carlo", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Write the chapter's plots, chi-square table and error-against-time data.
    Figures(FiguresArgs),
    /// Write warped sample points to a CSV file (columns x,y,pdf or x,y,z,pdf).
    Samples(SamplesArgs),
    /// This chapter renders no scene; see `figures` and `samples`.
    Render {
        /// Ignored.
        #[arg(trailing_var_arg = true, allow_hyphen_values = true, hide = true)]
        args: Vec<String>,
    },
}

#[derive(clap::Args, Debug)]
struct SamplesArgs {
    /// The warp: parallelogram, triangle, disc-naive, disc-polar, disc-concentric, sphere,
    /// hemisphere, cosine-hemisphere, cos-lobe, spherical-cap.
    #[arg(long)]
    warp: String,
    /// Number of points.
    #[arg(long, value_parser = clap::value_parser!(u64).range(1..=10_000_000))]
    n: u64,
    /// Seed of the uniform numbers.
    #[arg(long, default_value_t = 0)]
    seed: u64,
    /// Exponent of the cos-lobe warp.
    #[arg(long, allow_negative_numbers = true)]
    exponent: Option<f32>,
    /// Output CSV file.
    #[arg(long, value_name = "FILE.csv")]
    out: PathBuf,
}

fn main() -> ExitCode {
    let result = match Cli::parse().command {
        Command::Figures(args) => figures::write_all(&args.out, args.quick),
        Command::Samples(args) => write_samples(&args),
        Command::Render { .. } => Err(anyhow::anyhow!(
            "chapter 02 renders no scene: it studies estimators, random numbers and warps. \
             Try `figures --out DIR` or `samples --warp disc-polar --n 1000 --out FILE.csv`."
        )),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => report_error(error.as_ref()),
    }
}

fn write_samples(args: &SamplesArgs) -> anyhow::Result<()> {
    let warp = Warp::from_name(&args.warp, args.exponent).map_err(anyhow::Error::msg)?;
    check_writable(&args.out)?;
    let csv = samples_csv(&warp, args.n as usize, args.seed);
    workbench::output::write_text(&args.out, &csv)
        .with_context(|| format!("writing the samples of {}", warp.name()))?;
    Ok(())
}
