//! Checks every file given, each alone as a task of its own, in one process, and
//! prints how long the checks took: the cost of many small checks (a fuzz target's,
//! a language server's), where the fixed cost of a check shows.
//!
//! ```sh
//! cargo run --release -p rapid-sema --example check_each -- [--rounds N] FILE...
//! ```

use std::time::Instant;

use rapid_sema::{check, Options, SourceInput};

fn main() {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let mut rounds = 1usize;
    if args.first().is_some_and(|a| a == "--rounds") && args.len() >= 2 {
        rounds = args[1].parse().unwrap_or(1);
        args.drain(..2);
    }
    let files: Vec<SourceInput> = args
        .iter()
        .filter_map(|path| std::fs::read(path).ok().map(|bytes| SourceInput::from_bytes(path.clone(), bytes)))
        .collect();
    let options = Options::default();
    // The catalogue is parsed once per process either way: leave it out of the figure.
    let _ = check(&[SourceInput::from_text("warm.mod", "MODULE warm\nENDMODULE\n")], &options);
    let start = Instant::now();
    let mut diagnostics = 0;
    for _ in 0..rounds {
        for file in &files {
            diagnostics += check(std::slice::from_ref(file), &options).len();
        }
    }
    let elapsed = start.elapsed();
    let checks = rounds * files.len();
    #[allow(clippy::print_stdout)]
    {
        println!(
            "{checks} checks in {:.3} s ({:.1} us per check), {diagnostics} diagnostics",
            elapsed.as_secs_f64(),
            elapsed.as_secs_f64() * 1e6 / checks.max(1) as f64
        );
    }
}
