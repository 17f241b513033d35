//! Cross-connections (EIO_CROSS, manual §2.10): resolved to signal ids, checked for loops at
//! load, ordered so that one change re-evaluates every affected connection once, upstream
//! first, and evaluated as AND/OR/NOT expressions.

use std::collections::HashMap;

use crate::def::{ConfigError, CrossConnection, CrossOp, SignalDef, MAX_CROSS_TERMS};

/// One cross-connection with its signals resolved to ids.
#[derive(Debug, Clone)]
pub(crate) struct Cross {
    pub(crate) result: u32,
    pub(crate) terms: Vec<(u32, bool)>,
    pub(crate) ops: Vec<CrossOp>,
    /// Sort key: connections that feed another one come first; ties keep the configuration order.
    pub(crate) key: (u32, usize),
}

impl Cross {
    /// Evaluates the expression on the current digital values.
    // uncertain: AND binds tighter than OR (as in RAPID expressions); the system parameters
    // manual lists Oper1..Oper4 without stating a priority.
    pub(crate) fn eval(&self, values: &[f64]) -> bool {
        let term = |i: usize| {
            let (id, inverted) = self.terms[i];
            let on = values.get(id as usize).is_some_and(|v| *v != 0.0);
            on != inverted
        };
        let mut any = false;
        let mut all = term(0);
        for (i, op) in self.ops.iter().enumerate() {
            match op {
                CrossOp::And => all &= term(i + 1),
                CrossOp::Or => {
                    any |= all;
                    all = term(i + 1);
                }
            }
        }
        any || all
    }
}

/// Every cross-connection of the system and the indexes the propagation needs.
#[derive(Debug, Clone, Default)]
pub(crate) struct CrossNet {
    pub(crate) crosses: Vec<Cross>,
    /// For each signal id, the connections that read it (as an actor).
    pub(crate) readers: Vec<Vec<usize>>,
    /// For each signal id, whether some connection writes it.
    pub(crate) is_result: Vec<bool>,
}

impl CrossNet {
    pub(crate) fn build(
        defs: &[SignalDef],
        ids: &HashMap<String, u32>,
        crosses: &[CrossConnection],
    ) -> Result<CrossNet, ConfigError> {
        let mut resolved = Vec::with_capacity(crosses.len());
        for (index, cross) in crosses.iter().enumerate() {
            resolved.push(resolve(index, cross, defs, ids)?);
        }
        let depth = depths(defs, &resolved)?;
        let mut net =
            CrossNet { crosses: resolved, readers: vec![Vec::new(); defs.len()], is_result: vec![false; defs.len()] };
        for (index, cross) in net.crosses.iter_mut().enumerate() {
            let level = cross.terms.iter().map(|(id, _)| depth[*id as usize]).max().unwrap_or(0);
            cross.key = (level, index);
        }
        for (index, cross) in net.crosses.iter().enumerate() {
            net.is_result[cross.result as usize] = true;
            for (id, _) in &cross.terms {
                let readers = &mut net.readers[*id as usize];
                if !readers.contains(&index) {
                    readers.push(index);
                }
            }
        }
        Ok(net)
    }
}

fn resolve(
    index: usize,
    cross: &CrossConnection,
    defs: &[SignalDef],
    ids: &HashMap<String, u32>,
) -> Result<Cross, ConfigError> {
    let bad = |reason: String| ConfigError::BadCross { index, reason };
    if cross.terms.is_empty() {
        return Err(bad("it has no actor signal".to_string()));
    }
    if cross.terms.len() > MAX_CROSS_TERMS {
        return Err(bad(format!("it has {} actor signals; at most {MAX_CROSS_TERMS} are allowed", cross.terms.len())));
    }
    if cross.ops.len() + 1 != cross.terms.len() {
        return Err(bad(format!(
            "{} actor signals need {} operators, not {}",
            cross.terms.len(),
            cross.terms.len() - 1,
            cross.ops.len()
        )));
    }
    let lookup = |name: &str| -> Result<u32, ConfigError> {
        let id = *ids
            .get(&name.to_ascii_lowercase())
            .ok_or_else(|| ConfigError::UnknownCrossSignal { index, name: name.to_string() })?;
        let def = &defs[id as usize];
        if !def.kind.is_digital() {
            return Err(bad(format!(
                "`{}` is a {} signal; cross-connections join digital signals only",
                def.name, def.kind
            )));
        }
        Ok(id)
    };
    let result = lookup(&cross.result)?;
    let mut terms = Vec::with_capacity(cross.terms.len());
    for (name, inverted) in &cross.terms {
        terms.push((lookup(name)?, *inverted));
    }
    Ok(Cross { result, terms, ops: cross.ops.clone(), key: (0, index) })
}

/// The depth of every signal in the actor → result graph (0 for a signal no connection
/// writes), or the first loop found, searching signals and connections in configuration order.
fn depths(defs: &[SignalDef], crosses: &[Cross]) -> Result<Vec<u32>, ConfigError> {
    // For each signal, the connections that write it.
    let mut writers: Vec<Vec<usize>> = vec![Vec::new(); defs.len()];
    for (index, cross) in crosses.iter().enumerate() {
        writers[cross.result as usize].push(index);
    }
    let mut state = vec![Visit::New; defs.len()];
    let mut depth = vec![0u32; defs.len()];
    for start in 0..defs.len() {
        if state[start] == Visit::New {
            visit(start, defs, crosses, &writers, &mut state, &mut depth)?;
        }
    }
    Ok(depth)
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Visit {
    New,
    Open,
    Done,
}

/// Depth-first search from a signal towards the actors that drive it, with an explicit stack
/// (a long chain must not overflow the native one). An `Open` signal met again is a loop.
fn visit(
    start: usize,
    defs: &[SignalDef],
    crosses: &[Cross],
    writers: &[Vec<usize>],
    state: &mut [Visit],
    depth: &mut [u32],
) -> Result<(), ConfigError> {
    // Each frame: the signal, and how far through its (writer, actor) pairs we are.
    let mut stack: Vec<(usize, usize, usize)> = vec![(start, 0, 0)];
    state[start] = Visit::Open;
    while let Some(&mut (signal, ref mut writer, ref mut actor)) = stack.last_mut() {
        let Some(&cross_index) = writers[signal].get(*writer) else {
            state[signal] = Visit::Done;
            stack.pop();
            if let Some(&(parent, _, _)) = stack.last() {
                depth[parent] = depth[parent].max(depth[signal] + 1);
            }
            continue;
        };
        let cross = &crosses[cross_index];
        let Some(&(next, _)) = cross.terms.get(*actor) else {
            *writer += 1;
            *actor = 0;
            continue;
        };
        *actor += 1;
        let next = next as usize;
        match state[next] {
            Visit::Done => depth[signal] = depth[signal].max(depth[next] + 1),
            Visit::New => {
                state[next] = Visit::Open;
                stack.push((next, 0, 0));
            }
            Visit::Open => {
                // The stack from `next` up to `signal` is the loop, read against the arrows
                // (each signal is driven by the one after it); report it in signal-flow order.
                let from = stack.iter().position(|f| f.0 == next).unwrap_or(0);
                let mut path: Vec<String> = stack[from..].iter().rev().map(|f| defs[f.0].name.clone()).collect();
                path.insert(0, defs[next].name.clone());
                return Err(ConfigError::CrossLoop { index: cross_index, path });
            }
        }
    }
    Ok(())
}
