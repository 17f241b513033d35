//! Project automation. Today it only hosts the tidy test (`tests/tidy.rs`); tasks that
//! generate files live as tests beside what they generate (see `docs_fresh`).

fn main() {
    #[allow(clippy::print_stderr)]
    {
        eprintln!("usage: cargo test -p xtask (tidy checks); no other tasks yet");
    }
    std::process::exit(2);
}
