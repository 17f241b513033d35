//! The global persistents of a system (§1.20): one object per name for every task
//! that declares it. Each task keeps its own copy in its globals; the store holds the
//! current value, and the controller copies changes in before a task runs and out
//! after (tasks run one at a time, so no task ever sees a stale value). What a task
//! changed is looked for only among the globals its VM records as written.

use rapid_vm::exec::storage::GlobalWrites;
use rapid_vm::value::Value;
use rapid_vm::{Loaded, SharedPers};
use rustc_hash::FxHashMap;

use crate::types::{renumber, same, TypeMap};

/// One shared persistent.
#[derive(Debug)]
struct Entry {
    /// As first declared, for messages.
    name: String,
    type_name: String,
    dims: [u32; 3],
    value: Value,
    /// The task whose types `value` is numbered in.
    owner: usize,
    /// The store's generation when it last changed.
    changed: u64,
    /// A declaration with an initial value gave it its value.
    initialised: bool,
}

/// A task's view of the store: where each of its shared persistents lives.
#[derive(Debug, Default)]
pub(crate) struct TaskPers {
    /// (global in the task, entry in the store, the value the task had when last synced).
    slots: Vec<(u32, usize, Value)>,
    /// The slot of each of those globals.
    slot_of: FxHashMap<u32, usize>,
    /// The store generation the task has seen.
    seen: u64,
}

/// Every global persistent of the system, and the variables of shared modules.
#[derive(Debug, Default)]
pub struct PersStore {
    entries: Vec<Entry>,
    by_name: FxHashMap<String, usize>,
    /// Bumped by every change.
    pub generation: u64,
}

impl PersStore {
    /// Registers task `task`'s global persistents. A persistent another task declared
    /// already keeps its value (the first declaration creates the object), unless that
    /// declaration had no initial value and this one has (§1.2.2: a persistent without
    /// one takes the value the others give it); one with another type or size is the
    /// error of §1.20.
    pub(crate) fn register(
        &mut self,
        task: usize,
        task_name: &str,
        loaded: &Loaded,
        shared_files: &[usize],
    ) -> Result<TaskPers, String> {
        let mut view = TaskPers::default();
        // The variables of a module installed shared are one object too (TASK VAR
        // gives each task its own), kept apart from the persistents by their key.
        let shared_vars = loaded
            .module_vars
            .iter()
            .filter(|v| !v.task_scoped && shared_files.contains(&v.file))
            .map(|v| (format!("var {}", v.data.name.to_ascii_lowercase()), &v.data));
        let persistents = loaded.shared_pers.iter().map(|p| (p.name.to_ascii_lowercase(), p));
        for (key, pers) in persistents.chain(shared_vars) {
            let value = loaded.vm.global(pers.global).cloned().unwrap_or(Value::Absent);
            let idx = match self.by_name.get(&key) {
                Some(&idx) => {
                    check_same_shape(&self.entries[idx], pers, task_name)?;
                    let entry = &mut self.entries[idx];
                    if pers.initialised && !entry.initialised {
                        self.generation += 1;
                        (entry.value, entry.owner, entry.initialised) = (value.clone(), task, true);
                        entry.changed = self.generation;
                    }
                    idx
                }
                None => {
                    self.entries.push(Entry {
                        name: pers.name.clone(),
                        type_name: pers.type_name.clone(),
                        dims: pers.dims,
                        value: value.clone(),
                        owner: task,
                        changed: 1,
                        initialised: pers.initialised,
                    });
                    self.generation = self.generation.max(1);
                    self.by_name.insert(key, self.entries.len() - 1);
                    self.entries.len() - 1
                }
            };
            view.slot_of.insert(pers.global, view.slots.len());
            view.slots.push((pers.global, idx, value));
        }
        Ok(view)
    }

    /// The global persistents changed after store generation `generation` (for a
    /// front end's change stream): name as first declared, value, and the task whose
    /// record types the value is numbered in. The variables of shared modules are left
    /// out.
    pub(crate) fn changed_since(&self, generation: u64) -> impl Iterator<Item = (&str, &Value, usize)> {
        self.by_name
            .iter()
            .filter(|(key, _)| !key.starts_with("var "))
            .map(|(_, &idx)| &self.entries[idx])
            .filter(move |entry| entry.changed > generation)
            .map(|entry| (entry.name.as_str(), &entry.value, entry.owner))
    }

    /// Before task `task` runs: the changes made since it last looked, into its globals.
    pub(crate) fn copy_in(&self, task: usize, view: &mut TaskPers, vm: &mut rapid_vm::Vm, maps: &[Vec<TypeMap>]) {
        if view.seen == self.generation {
            return;
        }
        for (global, idx, last) in &mut view.slots {
            let entry = &self.entries[*idx];
            if entry.changed > view.seen && entry.owner != task {
                let value = renumber(&entry.value, &maps[entry.owner][task]);
                vm.sync_global(*global, value.clone());
                *last = value;
            }
        }
        view.seen = self.generation;
    }

    /// After task `task` ran: what it changed, into the store. Only the globals the
    /// task wrote since the last copy out can have changed (copy_in's writes are not
    /// recorded); a value written but left as it was changes nothing.
    pub(crate) fn copy_out(&mut self, task: usize, view: &mut TaskPers, vm: &mut rapid_vm::Vm) {
        match vm.global_writes() {
            GlobalWrites::All => {
                for slot in &mut view.slots {
                    self.copy_out_slot(task, slot, vm);
                }
            }
            GlobalWrites::Only(written) => {
                for global in written {
                    if let Some(&at) = view.slot_of.get(global) {
                        self.copy_out_slot(task, &mut view.slots[at], vm);
                    }
                }
            }
        }
        vm.clear_global_writes();
        // copy_in ran just before the task did, and no other task ran since: the
        // task holds every current value.
        view.seen = self.generation;
    }

    /// One shared persistent of task `task` into the store, if it changed.
    fn copy_out_slot(&mut self, task: usize, (global, idx, last): &mut (u32, usize, Value), vm: &rapid_vm::Vm) {
        let Some(now) = vm.global(*global) else { return };
        if same(now, last) {
            return;
        }
        *last = now.clone();
        self.generation += 1;
        let entry = &mut self.entries[*idx];
        entry.value = now.clone();
        entry.owner = task;
        entry.changed = self.generation;
    }
}

fn check_same_shape(entry: &Entry, pers: &SharedPers, task_name: &str) -> Result<(), String> {
    if entry.type_name.eq_ignore_ascii_case(&pers.type_name) && entry.dims == pers.dims {
        return Ok(());
    }
    Err(format!(
        "persistent `{}` is declared `{}` in one task and `{}` in task {task_name}: global persistents of \
         the same name must have the same type and size in every task",
        entry.name,
        shape(&entry.type_name, entry.dims),
        shape(&pers.type_name, pers.dims)
    ))
}

/// A persistent's type with its array sizes, as declared: `num{2,3}` (the same words
/// as `rapid check`'s system finding).
pub use rapid_sema::system::shape;
