//! `rapid dump-ir`: the compiled form of a program, one listing per routine
//! (`rapid_vm::disas`), printed without running anything.

use std::io::{self, BufWriter, Write};

use rapid_sema::Options;

use crate::args::DumpIrArgs;
use crate::commands::ExitStatus;
use rapid_controller::assembly::inputs;

pub(crate) fn run(args: &DumpIrArgs) -> anyhow::Result<ExitStatus> {
    let inputs = inputs::collect(&args.paths)?;
    let options = Options {
        predefined: inputs.predefined.clone(),
        system_options: inputs.system_options.clone(),
        ..Options::default()
    };
    let task = match rapid_vm::compile_files(&inputs.modules, &options, rapid_controller::builtin_set::standard()) {
        Ok(task) => task,
        Err(err) => return super::run::report_load_error(err, &inputs.modules),
    };
    let mut out = BufWriter::new(io::stdout().lock());
    let source = |file: usize| inputs.modules.get(file).map(|f| f.text.as_str());
    let mut first = true;
    let routines = &task.compiled.routines;
    for code in routines.iter().flatten() {
        if !first {
            writeln!(out)?;
        }
        first = false;
        let cx = rapid_vm::disas::Context { code, routines, globals: &task.global_names, builtins: &task.builtins };
        write!(out, "{}", rapid_vm::disas::list(&cx, source(code.file)))?;
    }
    out.flush()?;
    Ok(ExitStatus::Success)
}
