//! A task's own side of the system as it starts: its file devices (the controller
//! root, and the files its modules were loaded from, for ModExist and ModTimeDnum), the
//! configuration its ReadCfgData reads, and the controller's state (operating mode,
//! speed override) its built-ins see.

use std::path::PathBuf;

use rapid_config::CfgFile;
use rapid_sema::SourceInput;
use rapid_vm::builtins::controller::ControllerState;
use rapid_vm::world::devices::ModuleFile;
use rapid_vm::Loaded;

/// Sets task `loaded` up: `home` is the controller root of its file devices, `files`
/// the module files it was loaded from, `syspar` the configuration files with their
/// domains, `state` the controller's state.
pub fn configure(
    loaded: &mut Loaded,
    home: PathBuf,
    files: &[SourceInput],
    syspar: Vec<(String, CfgFile)>,
    state: ControllerState,
) {
    let resources = loaded.vm.resources_mut();
    resources.devices.set_root(home);
    resources.devices.set_modules(module_files(files));
    crate::bindings::cfgdata::of_mut(resources).set_config(Box::new(super::cfgdata::SysParams::new(syspar)));
    resources.controller = state;
}

/// The modules each readable file declares, with the file's path.
fn module_files(files: &[SourceInput]) -> Vec<ModuleFile> {
    let mut interner = rapid_syntax::Interner::default();
    files
        .iter()
        .filter(|f| f.unreadable.is_none())
        .flat_map(|f| {
            // Only the module names are needed: bodies are scanned over, not parsed.
            let parse = rapid_syntax::parse_outline(&f.text, &mut interner);
            let path = PathBuf::from(&f.path);
            let names: Vec<String> = parse.file.modules.iter().map(|m| m.name.span.text(&f.text).to_string()).collect();
            names.into_iter().map(move |name| ModuleFile { name, path: path.clone() })
        })
        .collect()
}
