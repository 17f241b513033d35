//! Project automation. `cargo run -p xtask -- builtins-doc` writes `docs/builtins.md`
//! and the generated section of `docs/coverage.md` from the catalogue and the
//! interpreter's registry; the tidy test (`tests/tidy.rs`)
//! and the freshness test of each generated file run under `cargo test`. Other
//! generated files still live as tests beside what they generate (see `docs_fresh`).

mod builtins_doc;
mod coverage_doc;

/// What `cargo run -p xtask` can do.
const USAGE: &str = "usage: cargo run -p xtask -- builtins-doc   (writes docs/builtins.md and the generated \
                     section of docs/coverage.md)\n\
                     cargo test -p xtask runs the tidy checks and the freshness tests";

fn main() {
    let task = std::env::args().nth(1);
    let code = match task.as_deref() {
        Some("builtins-doc") => match builtins_doc::write(&builtins_doc::root()) {
            Ok(()) => {
                report(&format!("wrote {} and {}", builtins_doc::PATH, coverage_doc::PATH));
                0
            }
            Err(err) => {
                report(&format!("cannot write {} or {}: {err}", builtins_doc::PATH, coverage_doc::PATH));
                1
            }
        },
        _ => {
            report(USAGE);
            2
        }
    };
    std::process::exit(code);
}

#[allow(clippy::print_stderr)]
fn report(text: &str) {
    eprintln!("{text}");
}
