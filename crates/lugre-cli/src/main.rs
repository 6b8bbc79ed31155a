//! `lugre`: hysteresis and minor loops of the LuGre and Dahl friction models.
//!
//! Exit status: 0 success, 2 bad input or usage, 1 internal error (a bug).

use clap::Parser;
use lugre_cli::Cli;
use std::io::Write;
use std::process::ExitCode;

fn main() -> ExitCode {
    // One line and status 1 for a bug, never a backtrace (RUST_BACKTRACE is set on the
    // machines users run us on).
    std::panic::set_hook(Box::new(|info| {
        let msg = info
            .payload()
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| info.payload().downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "unknown panic".into());
        let at = info
            .location()
            .map(|l| format!(" at {}:{}", l.file(), l.line()))
            .unwrap_or_default();
        let _ = writeln!(
            std::io::stderr(),
            "lugre: internal error (please report): {}{at}",
            one_line(&msg)
        );
    }));

    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => return clap_error(e),
    };
    let result = std::panic::catch_unwind(|| cli.run());
    match result {
        Ok(Ok(())) => ExitCode::SUCCESS,
        // A reader that stopped early (`| head`) is not an error.
        Ok(Err(e)) if is_broken_pipe(&e) => ExitCode::SUCCESS,
        Ok(Err(e)) => {
            let _ = writeln!(
                std::io::stderr(),
                "lugre: error: {}",
                one_line(&format!("{e:#}"))
            );
            ExitCode::from(2)
        }
        Err(_) => ExitCode::from(1),
    }
}

/// Help and version go to stdout with status 0; every other clap error becomes one line.
fn clap_error(e: clap::Error) -> ExitCode {
    use clap::error::ErrorKind;
    match e.kind() {
        ErrorKind::DisplayHelp
        | ErrorKind::DisplayVersion
        | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            let _ = e.print();
            if e.kind() == ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand {
                ExitCode::from(2)
            } else {
                ExitCode::SUCCESS
            }
        }
        _ => {
            let text = e.render().to_string();
            // clap's message is the paragraph before the first blank line.
            let head: Vec<&str> = text
                .lines()
                .take_while(|l| !l.trim().is_empty())
                .map(str::trim)
                .collect();
            let msg = head.join(" ");
            let msg = msg.strip_prefix("error: ").unwrap_or(&msg);
            // clap quotes a bad argument whole, however long.
            let msg = lugre_cli::shorten_quoted(msg);
            let _ = writeln!(
                std::io::stderr(),
                "lugre: error: {msg} (see 'lugre --help')"
            );
            ExitCode::from(2)
        }
    }
}

fn is_broken_pipe(e: &anyhow::Error) -> bool {
    e.chain().any(|c| {
        c.downcast_ref::<std::io::Error>()
            .is_some_and(|io| io.kind() == std::io::ErrorKind::BrokenPipe)
    })
}

/// `s` on one line: runs of whitespace become one space, and other control characters (a NUL
/// or an escape sequence from a file's contents) are shown escaped, not sent to the terminal.
fn one_line(s: &str) -> String {
    lugre_io::text::printable(&s.split_whitespace().collect::<Vec<_>>().join(" "))
}
