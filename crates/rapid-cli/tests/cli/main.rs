//! The `rapid` command end to end: one test binary for every CLI test (one link, one
//! process per `cargo test`), one module per area, and one fixture (`fixture.rs`)
//! they share: running the command, scratch folders, backups of several tasks.
//! Committed inputs are in `fixtures/` (and the repository's `tests/`, `examples/`),
//! insta snapshots in `snapshots/` (named `cli__MODULE__TEST.snap`).
//!
//! One module's tests: `cargo test -p rapid-cli --test cli -- backup::`.
//! The conformance corpus is its own binary (`tests/conformance.rs`).

mod external_fixture;
mod fixture;

mod backup;
mod backup_home_modules;
mod check;
mod check_system;
mod check_tasks;
mod controller_state;
mod conveyor;
mod coordinated;
mod correction;
mod dap;
mod dump_ir;
mod elog;
mod error_location;
mod examples;
mod external_axes;
mod external_paths;
mod files;
mod fmt;
mod interrupt;
mod iomore;
mod layouts;
mod limits;
mod lsp;
mod manifest;
mod mech_units;
mod multimove;
mod multitask;
mod multitask_steps;
mod options;
mod path;
mod pers_writes;
mod report;
mod robot_numbers;
mod robots;
mod run;
mod run_loop;
mod sarif;
mod save_pers;
mod scale;
mod search;
mod serve;
mod serve_ampe;
mod serve_ampe_protocol;
mod serve_controller_ip;
mod serve_faults;
mod sockets;
mod sockets_controller_ip;
mod sockets_system;
mod stepbwd;
mod symsearch;
mod system_signals;
mod triggers;
mod virtual_signals;
mod vscode;
mod yumi;
mod zones;
