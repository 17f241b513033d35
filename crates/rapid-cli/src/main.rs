//! The `rapid` command.
fn main() {}
