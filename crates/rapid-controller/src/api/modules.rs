//! A task's program modules for front ends (RWS `loadmod`/`unloadmod`, module text):
//! list them, show one's text, load a module file from a file device, unload one by
//! name. Loading and unloading
//! are the task's own Load and EraseModule (`rapid_vm::exec::modules`), asked for
//! while the program is stopped, as the controller asks for it.

use super::{ApiError, Session};

/// A module's attributes as the controller reports them.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ModuleInfo {
    /// The name as the module declares it.
    pub name: String,
    /// The path of the file it was loaded from, as the task was given it.
    pub file: String,
    /// Its module attributes in the order RAPID writes them: `SYSMODULE`, `NOVIEW`,
    /// `NOSTEPIN`, `VIEWONLY`, `READONLY`.
    pub attributes: Vec<&'static str>,
}

impl Session {
    /// The modules of task `task`: those it started with, then those loaded since.
    pub fn modules(&self, task: &str) -> Result<Vec<String>, ApiError> {
        let idx = self.task_index(task)?;
        Ok(self.controller.tasks[idx].loaded.vm.module_names())
    }

    /// The text of module `module` of task `task` as program memory holds it: the
    /// module as loaded, with its persistents' current values written in (what Save
    /// would write). Allowed while the program runs: it only reads.
    pub fn module_text(&self, task: &str, module: &str) -> Result<String, ApiError> {
        let idx = self.task_index(task)?;
        let vm = &self.controller.tasks[idx].loaded.vm;
        if !vm.module_names().iter().any(|m| m.eq_ignore_ascii_case(module)) {
            return Err(ApiError::NotFound(format!("task {task} has no module `{module}`")));
        }
        vm.module_text_now(module)
            .ok_or_else(|| ApiError::Failed(format!("the text of module `{module}` cannot be made")))
    }

    /// The attributes of module `module` of task `task`: its name, the file it came
    /// from and its module attributes, read from the module's heading as loaded.
    pub fn module_info(&self, task: &str, module: &str) -> Result<ModuleInfo, ApiError> {
        let idx = self.task_index(task)?;
        let vm = &self.controller.tasks[idx].loaded.vm;
        let Some(name) = vm.module_names().into_iter().find(|m| m.eq_ignore_ascii_case(module)) else {
            return Err(ApiError::NotFound(format!("task {task} has no module `{module}`")));
        };
        // The program's files, those it started with then those loaded since; a module
        // unloaded and loaded again is in a later file, so the last one found is live.
        let mut found = None;
        for file in (0..).map_while(|i| vm.program_source(i)) {
            let mut interner = rapid_syntax::Interner::default();
            let parse = rapid_syntax::parse_outline(&file.text, &mut interner);
            for m in &parse.file.modules {
                // The interner folds letter case: the name as written comes from the task.
                if interner.resolve(m.name.sym).eq_ignore_ascii_case(module) {
                    let attributes = m.attrs.iter().map(|(a, _)| attribute_word(*a)).collect();
                    found = Some(ModuleInfo { name: name.clone(), file: file.path.clone(), attributes });
                }
            }
        }
        found.ok_or_else(|| ApiError::Failed(format!("the heading of module `{module}` cannot be read")))
    }

    /// Loads the module file at RAPID path `path` (`HOME:/extra.mod`) into task `task`
    /// of the stopped program: it is checked against the task's program and linked,
    /// its data initialised.
    pub fn load_module(&mut self, task: &str, path: &str) -> Result<(), ApiError> {
        self.must_be_stopped()?;
        let idx = self.task_index(task)?;
        let files = &self.controller.tasks[idx].loaded.vm.resources().devices;
        let request = rapid_vm::builtins::modules::front_end_load(files, path).map_err(ApiError::NotFound)?;
        let outcome =
            self.controller.with_task(idx, &mut self.pendant, |vm, host| vm.front_end_module_request(request, host));
        self.gather();
        outcome.map_err(|e| ApiError::Refused(format!("task {task} cannot load `{path}`: {}", e.message)))
    }

    /// Unloads module `module` from task `task` of the stopped program (as
    /// EraseModule does).
    pub fn unload_module(&mut self, task: &str, module: &str) -> Result<(), ApiError> {
        self.must_be_stopped()?;
        let idx = self.task_index(task)?;
        if !self.modules(task)?.iter().any(|m| m.eq_ignore_ascii_case(module)) {
            return Err(ApiError::NotFound(format!("task {task} has no module `{module}`")));
        }
        let request = rapid_vm::builtins::modules::ModuleRequest::Erase { module: module.to_owned() };
        let outcome =
            self.controller.with_task(idx, &mut self.pendant, |vm, host| vm.front_end_module_request(request, host));
        self.gather();
        outcome.map_err(|e| ApiError::Refused(format!("task {task} cannot unload `{module}`: {}", e.message)))
    }
}

/// A module attribute as RAPID writes it.
fn attribute_word(attr: rapid_syntax::ast::ModuleAttr) -> &'static str {
    use rapid_syntax::ast::ModuleAttr as A;
    match attr {
        A::Sysmodule => "SYSMODULE",
        A::Noview => "NOVIEW",
        A::Nostepin => "NOSTEPIN",
        A::Viewonly => "VIEWONLY",
        A::Readonly => "READONLY",
    }
}
