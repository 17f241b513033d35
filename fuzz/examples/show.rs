//! Prints the RAPID program the `program` fuzz target generates from an input file, to
//! turn a finding into a regression test: `cargo run --manifest-path fuzz/Cargo.toml
//! --example show -- fuzz/artifacts/program/crash-…`.

fn main() {
    let path = std::env::args().nth(1).expect("usage: show INPUT");
    let data = std::fs::read(&path).expect("read the input");
    let mut u = arbitrary::Unstructured::new(&data);
    match rapid_fuzz::program::generate(&mut u) {
        Ok(program) => {
            for (idx, module) in program.modules.iter().enumerate() {
                println!("! m{idx}.mod\n{module}");
            }
        }
        Err(err) => eprintln!("no program: {err}"),
    }
}
