//! The command line: the parser, the commands, and the dispatch to them (the only place that
//! names every command).

use anyhow::Result;
use clap::{Parser, Subcommand};

use crate::commands::{cycles, dynamics, fit, loops, paper, simulate, sweep};

#[derive(Parser, Debug)]
#[command(
    name = "lugre",
    version,
    about = "Hysteresis loops and minor loops of the LuGre and Dahl friction models",
    long_about = "Hysteresis loops and every minor loop of the LuGre and Dahl friction models, \
                  exact and stable at any stiffness (Ikhouane, Mañosa, Pujol: \"Minor loops of \
                  the Dahl and LuGre models\").\n\nExit status: 0 success, 2 bad input or usage, \
                  1 internal error."
)]
pub struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// The hysteresis loop y° and every minor loop of a periodic input, with energies.
    Loop(loops::LoopArgs),
    /// Minor loops in a measured history: reversals, ASTM E1049 rainflow cycles, where each
    /// loop closes, and (with a model) the energy over each loop.
    Cycles(cycles::CyclesArgs),
    /// The response y_gamma of eq. 5 (gamma = 1: eq. 1; gamma = inf: y*_u, eq. 6) to a periodic
    /// input, sampled data or a sine: exact for piecewise-linear inputs at any stiffness.
    Simulate(simulate::SimulateArgs),
    /// The periodic steady state under sines over a grid of amplitudes and frequencies:
    /// energy dissipated per cycle, peak force, equivalent stiffness and damping, describing
    /// function (gain and phase), and the loops; exact fixed point of the period map, in
    /// parallel.
    Sweep(sweep::SweepArgs),
    /// Parameter identification from a measured record: sigma0 and g(0) from a slow loop
    /// (--fit slow, columns u,F), or the full LuGre set from rate-dependent data (--fit full,
    /// columns t,u,F), with standard errors and 95 % confidence intervals.
    Fit(fit::FitArgs),
    /// A mass with LuGre friction driven by a force, a spring, a PID controller or a
    /// prescribed velocity, solved to a stated tolerance with the velocity's sign changes
    /// located; --scenario runs the experiments of Canudas de Wit et al. (1995).
    Dynamics(dynamics::DynamicsArgs),
    /// Redraw the paper's Figures 3-17 (SVG, PNG, the CSV of every curve) and write
    /// index.html: every figure with its caption, each example's loop numbers, and the errata
    /// of Theorem A.
    Paper(paper::PaperArgs),
}

impl Cli {
    /// Runs the command given.
    pub fn run(self) -> Result<()> {
        match self.command {
            Command::Loop(args) => loops::run(&args),
            Command::Cycles(args) => cycles::run(&args),
            Command::Simulate(args) => simulate::run(&args),
            Command::Sweep(args) => sweep::run(&args),
            Command::Fit(args) => fit::run(&args),
            Command::Dynamics(args) => dynamics::run(&args),
            Command::Paper(args) => paper::run(&args),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    #[test]
    fn the_parser_is_consistent_and_every_flag_has_help() {
        let cli = Cli::command();
        cli.clone().debug_assert();
        for command in cli.get_subcommands() {
            for arg in command.get_arguments() {
                assert!(
                    arg.get_help().is_some(),
                    "lugre {} --{}: no help",
                    command.get_name(),
                    arg.get_id()
                );
            }
        }
    }
}
