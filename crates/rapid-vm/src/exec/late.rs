//! Late binding (`% name % args`, CallByVar): the procedure is found by name when the
//! call runs, and the arguments as written (by position, by name, optional, switches,
//! conditional) are matched to its parameters then, by the rules of a call (§1.3.4):
//! a positional argument takes the next required parameter, `\Name` an optional one,
//! a switch only a switch parameter, one alternative per group, every required
//! parameter given. A call the procedure cannot take raises ERR_CALLPROC.

use super::{Exit, Vm};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::ir::{Code, LateArg, LateArgKind, ParamMeta};
use crate::value::Value;

impl Vm {
    /// `% name % args`: finds the procedure by name at run time and enters it.
    pub(super) fn late_call(&mut self, code: &Code, site: u32) -> Result<Option<Exit>, RapidError> {
        let site = &code.sites[site as usize];
        let at = self.storage.stack.len() - site.n_pushed as usize;
        let pushed = self.storage.stack.split_off(at);
        let name = match self.pop() {
            Value::Str(name) => name,
            _ => return Err(self.error(Err::CallProc, "the procedure name is not a string")),
        };
        let Some(&idx) = self.procs_by_name.get(&name.to_lowercase()) else {
            return Err(self.error(Err::RefUnknownProc, format!("no procedure `{name}` is loaded")));
        };
        let Some(callee) = self.routines.get(idx as usize).cloned().flatten() else {
            return Err(self.error(Err::RefUnknownProc, format!("no procedure `{name}` is loaded")));
        };
        if callee.is_func || callee.is_trap {
            return Err(self.error(Err::CallProc, format!("`{name}` is not a procedure")));
        }
        let slots = match bind(&callee.param_meta, &site.late_args) {
            Ok(slots) => slots,
            Err(why) => return Err(self.error(Err::CallProc, format!("`{name}` cannot be called so: {why}"))),
        };
        let caller_base = self.frame().base;
        let mut pushed = pushed.into_iter();
        let mut args = vec![Value::Absent; callee.param_meta.len()];
        for (late, slot) in site.late_args.iter().zip(slots) {
            let by_ref = callee.param_by_ref.get(slot).copied().unwrap_or(false);
            let value = match late.kind {
                LateArgKind::Switch => Value::SwitchOn,
                LateArgKind::Conditional(local) => self.forward(caller_base + local, by_ref)?,
                LateArgKind::Pushed => match (pushed.next().unwrap_or(Value::Absent), late.by_ref, by_ref) {
                    (Value::Ref(place), true, true) => Value::Ref(place),
                    (Value::Ref(place), true, false) => self.storage.get(&place).map_err(|f| self.fault(f))?.clone(),
                    (_, false, true) => {
                        return Err(
                            self.error(Err::CallProc, format!("`{name}` needs data, not a value, for an argument"))
                        )
                    }
                    (value, _, _) => value,
                },
            };
            args[slot] = value;
        }
        self.enter(callee, args)
    }
}

/// The parameter each argument goes to, or why the procedure cannot take them.
fn bind(params: &[ParamMeta], args: &[LateArg]) -> Result<Vec<usize>, String> {
    let mut taken = vec![false; params.len()];
    let mut slots = Vec::with_capacity(args.len());
    let mut cursor = 0usize;
    for arg in args {
        let slot = match &arg.name {
            Some(name) => {
                params.iter().position(|p| *p.name == **name).ok_or_else(|| format!("no parameter `{name}`"))?
            }
            None if arg.optional => return Err("an optional argument without a name".into()),
            None => {
                // The next required parameter (the first of its group) not yet given.
                let found = (cursor..params.len()).find(|&p| {
                    !params[p].optional
                        && (p == 0 || params[p - 1].group != params[p].group)
                        && !group_taken(params, &taken, p)
                });
                found.ok_or("too many arguments")?
            }
        };
        let param = &params[slot];
        if param.optional != arg.optional {
            let want = if param.optional { "optional (written with \\)" } else { "required" };
            return Err(format!("parameter `{}` is {want}", param.name));
        }
        // A conditional argument passes on whatever the caller was given.
        let conditional = matches!(arg.kind, LateArgKind::Conditional(_));
        if !conditional && param.switch != (arg.kind == LateArgKind::Switch) {
            let what = if param.switch { "a switch, which takes no value" } else { "not a switch: it needs a value" };
            return Err(format!("parameter `{}` is {what}", param.name));
        }
        if group_taken(params, &taken, slot) {
            return Err(format!("parameter `{}` (or an alternative to it) is given twice", param.name));
        }
        taken[slot] = true;
        if !param.optional {
            cursor = slot + 1;
        }
        slots.push(slot);
    }
    let missing = (0..params.len())
        .filter(|&p| !params[p].optional && (p == 0 || params[p - 1].group != params[p].group))
        .find(|&p| !group_taken(params, &taken, p));
    if let Some(p) = missing {
        return Err(format!("no argument for parameter `{}`", params[p].name));
    }
    Ok(slots)
}

/// Whether parameter `p` or another of its group of alternatives already has an argument.
fn group_taken(params: &[ParamMeta], taken: &[bool], p: usize) -> bool {
    let group = params[p].group;
    let (mut start, mut end) = (p, p + 1);
    while start > 0 && params[start - 1].group == group {
        start -= 1;
    }
    while end < params.len() && params[end].group == group {
        end += 1;
    }
    taken[start..end].iter().any(|&t| t)
}
