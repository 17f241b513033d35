//! Where values live: the globals and the value stack of all frames, and reading and
//! writing through places.

use crate::errnames::Err;
use crate::value::{PathStep, Place, Root, Value};

/// Globals (predefined and module data) and the frames' slots and operands.
#[derive(Debug, Default)]
pub struct Storage {
    pub globals: Globals,
    pub stack: Vec<Value>,
}

/// The globals, and which of them were written since the record was last cleared: a
/// controller compares only those with what the other tasks share (comparing every
/// shared persistent after each statement cost most of a multi-task run's time).
/// Every write goes through [`Globals::get_mut`] or replaces the whole vector, so none
/// is missed; a value written but unchanged is recorded too (the reader compares).
#[derive(Debug, Default)]
pub struct Globals {
    values: Vec<Value>,
    /// Per global, whether it is in `list` (as long as `values`).
    marked: Vec<bool>,
    /// The globals written, each once.
    list: Vec<u32>,
    /// The whole vector was replaced or grown: every global counts as written.
    all: bool,
}

/// Which globals were written since the record was last cleared.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GlobalWrites<'a> {
    /// These (each once, in no particular order).
    Only(&'a [u32]),
    /// Any of them.
    All,
}

impl Globals {
    /// Globals with their initial values: all of them count as written.
    pub fn new(values: Vec<Value>) -> Globals {
        let marked = vec![false; values.len()];
        Globals { values, marked, list: Vec::new(), all: true }
    }

    /// The value of global `idx`.
    #[inline]
    pub fn get(&self, idx: u32) -> Option<&Value> {
        self.values.get(idx as usize)
    }

    /// Every global, to read.
    #[inline]
    pub fn values(&self) -> &[Value] {
        &self.values
    }

    /// Global `idx` to write: recorded as written.
    #[inline]
    pub fn get_mut(&mut self, idx: u32) -> Option<&mut Value> {
        let value = self.values.get_mut(idx as usize)?;
        if !self.all {
            if let Some(marked) = self.marked.get_mut(idx as usize) {
                if !*marked {
                    *marked = true;
                    self.list.push(idx);
                }
            }
        }
        Some(value)
    }

    /// Gives global `idx` a value without recording the write: the controller
    /// bringing in what another task changed, which is no change of this task's.
    pub fn sync(&mut self, idx: u32, value: Value) {
        if let Some(slot) = self.values.get_mut(idx as usize) {
            *slot = value;
        }
    }

    /// Replaces every global (PP to main's initial values): all count as written.
    /// The old values are returned.
    pub fn replace(&mut self, values: Vec<Value>) -> Vec<Value> {
        self.mark_all();
        self.marked = vec![false; values.len()];
        std::mem::replace(&mut self.values, values)
    }

    /// Makes room for `n` globals (a module loaded), new ones `Absent`: all count as
    /// written.
    pub fn grow(&mut self, n: usize) {
        if self.values.len() < n {
            self.values.resize(n, Value::Absent);
            self.marked.resize(n, false);
        }
        self.mark_all();
    }

    fn mark_all(&mut self) {
        for &idx in &self.list {
            self.marked[idx as usize] = false;
        }
        self.list.clear();
        self.all = true;
    }

    /// The globals written since [`Globals::clear_writes`].
    pub fn writes(&self) -> GlobalWrites<'_> {
        if self.all {
            GlobalWrites::All
        } else {
            GlobalWrites::Only(&self.list)
        }
    }

    /// Starts a new record: nothing written.
    pub fn clear_writes(&mut self) {
        self.mark_all();
        self.all = false;
    }
}

/// A storage fault: the RAPID error and a message.
pub type Fault = (Err, String);

impl Storage {
    fn root(&self, root: Root) -> Option<&Value> {
        match root {
            Root::Global(i) => self.globals.get(i),
            Root::Stack(i) => self.stack.get(i as usize),
        }
    }

    fn root_mut(&mut self, root: Root) -> Option<&mut Value> {
        match root {
            Root::Global(i) => self.globals.get_mut(i),
            Root::Stack(i) => self.stack.get_mut(i as usize),
        }
    }

    /// The value at a place.
    pub fn get(&self, place: &Place) -> Result<&Value, Fault> {
        let mut value = self.root(place.root).ok_or_else(dangling)?;
        for &step in &place.path {
            value = value.step(step).ok_or_else(dangling)?;
        }
        Ok(value)
    }

    pub fn get_mut(&mut self, place: &Place) -> Result<&mut Value, Fault> {
        let mut value = self.root_mut(place.root).ok_or_else(dangling)?;
        for &step in &place.path {
            value = value.step_mut(step).ok_or_else(dangling)?;
        }
        Ok(value)
    }

    /// Stores `value` at `place`, converted to the numeric kind already there (a dnum
    /// variable stays a dnum when given a num, and the other way round).
    pub fn set(&mut self, place: &Place, value: Value) -> Result<(), Fault> {
        let slot = self.get_mut(place)?;
        *slot = coerce_like(slot, value)?;
        Ok(())
    }
}

fn dangling() -> Fault {
    (Err::ArgValue, "reference to data that no longer exists".into())
}

/// `value` converted to the numeric kind of `like` (num <-> dnum); other values as
/// they are.
pub fn coerce_like(like: &Value, value: Value) -> Result<Value, Fault> {
    match (like, value) {
        (Value::Dnum(_), Value::Num(n)) => Ok(Value::Dnum(f64::from(n))),
        (Value::Num(_), Value::Dnum(d)) => {
            if d.is_finite() && d.abs() <= f64::from(f32::MAX) {
                Ok(Value::Num(d as f32))
            } else {
                Err((Err::NumLimit, format!("the dnum {d} does not fit in a num")))
            }
        }
        (_, value) => Ok(value),
    }
}

/// The flat index of element `indices` (1-based) of an array with `dims`.
pub fn element_index(dims: [u32; 3], indices: &[f64]) -> Result<u32, Fault> {
    let rank = dims.iter().take_while(|&&d| d > 0).count();
    if indices.len() != rank {
        return Err((Err::IllegalDim, format!("{} indices for an array of {rank} dimensions", indices.len())));
    }
    let mut flat: u64 = 0;
    for (k, &index) in indices.iter().enumerate() {
        let size = dims[k];
        if index.fract() != 0.0 || index < 1.0 || index > f64::from(size) {
            return Err((Err::OutOfBounds, format!("index {index} is outside 1..{size}")));
        }
        flat = flat * u64::from(size) + (index as u64 - 1);
    }
    Ok(flat as u32)
}

/// Appends an element step to a place after checking the array there.
pub fn index_place(storage: &Storage, mut place: Place, indices: &[f64]) -> Result<Place, Fault> {
    let dims = match storage.get(&place)? {
        Value::Array(array) => array.dims,
        _ => return Err((Err::ArgValue, "indexing data that is not an array".into())),
    };
    let flat = element_index(dims, indices)?;
    place.path.push(PathStep::Element(flat));
    Ok(place)
}
