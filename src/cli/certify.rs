//! `ppm certify --max-degree M [--jobs N] [--shard K/N]`, `ppm certify merge FILES...` and
//! `ppm certify attach FILE`.

use crate::certify::{
    all_configs, attach_f64_bounds, merge, read_certificate, run_with as prove_all, shard,
    summary_table, write_certificate, write_text, Certificate, CertifyError, Model, Settings,
};
use clap::{Args, Subcommand};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// Arguments of `ppm certify`.
#[derive(Args, Debug)]
pub(super) struct CertifyArgs {
    /// `ppm certify merge …`: join shard certificates instead of proving.
    #[command(subcommand)]
    pub merge: Option<MergeCmd>,
    /// Largest vertex degree; all configurations with degrees 3..=M are proven.
    #[arg(long, default_value_t = 7)]
    pub max_degree: u32,
    /// Worker threads.
    #[arg(long, default_value_t = 2)]
    pub jobs: usize,
    /// Only shard K of N (1-based), e.g. `--shard 2/8`.
    #[arg(long)]
    pub shard: Option<String>,
    /// Certificate output: JSON, gzip-compressed when the name ends in `.gz`.
    #[arg(long, default_value = "certificate.json")]
    pub out: PathBuf,
    /// Readable summary output (Markdown); printed to stdout as well.
    #[arg(long)]
    pub summary: Option<PathBuf>,
    /// Planted fault: add this to the lens radius cos(π/6).
    #[arg(long, default_value_t = 0.0)]
    pub planted_lens_offset: f64,
    /// Planted fault: add this to the label in R_(u,w)⁻¹.
    #[arg(long, default_value_t = 0)]
    pub planted_label_shift: i64,
}

/// The `merge` subcommand of `ppm certify`.
#[derive(Subcommand, Debug)]
pub(super) enum MergeCmd {
    /// Join shard certificates into one.
    Merge {
        /// Shard certificate files to join (JSON or `*.json.gz`).
        files: Vec<PathBuf>,
        /// Merged certificate output: JSON, gzip-compressed when the name ends in `.gz`.
        #[arg(long, default_value = "certificate.json")]
        out: PathBuf,
        /// Readable summary output (Markdown); printed to stdout as well.
        #[arg(long)]
        summary: Option<PathBuf>,
    },
    /// Add the derived f64 bounds of every property (SPEC `CERT-f64-props`) to a complete
    /// certificate written before them: same results in the same order, nothing proven again.
    Attach {
        /// The certificate (JSON or `*.json.gz`).
        file: PathBuf,
        /// Output: JSON, gzip-compressed when the name ends in `.gz` (may be `file` itself).
        #[arg(long)]
        out: PathBuf,
        /// Readable summary output (Markdown); printed to stdout as well.
        #[arg(long)]
        summary: Option<PathBuf>,
    },
}

fn emit(cert: &Certificate, out: &Path, summary: Option<&Path>) -> Result<(), CertifyError> {
    write_certificate(cert, out)?;
    let table = summary_table(cert);
    if let Some(p) = summary {
        write_text(p, &table)?;
    }
    println!("{table}");
    Ok(())
}

fn parse_shard(s: &str) -> Result<(usize, usize), CertifyError> {
    let bad = || CertifyError::BadArg(format!("--shard {s}: expected K/N with 1 ≤ K ≤ N"));
    let (k, n) = s.split_once('/').ok_or_else(bad)?;
    let k: usize = k.trim().parse().map_err(|_| bad())?;
    let n: usize = n.trim().parse().map_err(|_| bad())?;
    if k == 0 || n == 0 || k > n {
        return Err(bad());
    }
    Ok((k, n))
}

fn run_inner(a: CertifyArgs) -> Result<bool, CertifyError> {
    match a.merge {
        Some(MergeCmd::Merge {
            files,
            out,
            summary,
        }) => {
            let parts = files
                .iter()
                .map(|f| read_certificate(f))
                .collect::<Result<Vec<_>, _>>()?;
            let cert = merge(parts)?;
            emit(&cert, &out, summary.as_deref())?;
            return Ok(true);
        }
        Some(MergeCmd::Attach { file, out, summary }) => {
            let mut cert = read_certificate(&file)?;
            if cert.shard.is_some() {
                return Err(CertifyError::BadArg(format!(
                    "{}: a shard; merge the shards (the merge adds the bounds)",
                    file.display()
                )));
            }
            attach_f64_bounds(&mut cert);
            emit(&cert, &out, summary.as_deref())?;
            return Ok(true);
        }
        None => {}
    }
    if a.max_degree < 3 || a.max_degree > 64 {
        return Err(CertifyError::BadArg(format!(
            "--max-degree {} (3..=64)",
            a.max_degree
        )));
    }
    let model = Model {
        lens_radius_offset: a.planted_lens_offset,
        label_shift: a.planted_label_shift,
        fault: None,
    };
    let all = all_configs(a.max_degree);
    let sh = a.shard.as_deref().map(parse_shard).transpose()?;
    let configs = match sh {
        Some((k, n)) => shard(&all, k, n),
        None => all,
    };
    let line = super::progress::Line::new("ppm certify", "configurations", true);
    let hook = line.hook();
    let cert = prove_all(
        &configs,
        a.max_degree,
        &model,
        &Settings::default(),
        a.jobs,
        sh,
        hook.as_ref().map(|h| h as _),
    );
    line.finish();
    let cert = cert?;
    emit(&cert, &a.out, a.summary.as_deref())?;
    Ok(true)
}

/// Entry point of `ppm certify`.
pub(super) fn run(a: CertifyArgs) -> ExitCode {
    match run_inner(a) {
        Ok(_) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("ppm certify: {e}");
            ExitCode::from(2)
        }
    }
}
