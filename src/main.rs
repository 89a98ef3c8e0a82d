//! The `blackhole` binary: parses the command line and dispatches; every
//! command lives in `blackhole::cli`.

use std::process::ExitCode;

use clap::Parser;

fn main() -> ExitCode {
    env_logger::Builder::from_env(env_logger::Env::default().default_filter_or("blackhole=info"))
        .format_timestamp(None)
        .init();
    match blackhole::cli::run(blackhole::cli::Cli::parse()) {
        Ok(code) => code,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(e.exit_code() as u8)
        }
    }
}
