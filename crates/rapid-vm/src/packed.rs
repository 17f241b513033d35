//! Constant aggregates held compactly: a routine's aggregates whose every leaf is a
//! literal (`[[500,0,400],[1,0,0,0],[0,0,0,0],[9E9,…]]`) are built once by the
//! compiler and kept as a shape (the record and array structure, shared by every
//! constant of that structure) and their leaves as plain 32-bit words. `Instr::
//! Aggregate` materialises the value each time it runs, as `MakeRecord` did from the
//! leaves it was given.
//!
//! Why: CAM and offline-programming modules are hundreds of thousands of moves with
//! inline robtargets. Built by instructions, a robtarget was 23 instructions and 17
//! pooled `Value`s (about 1 KB); as `Value`s, five records (about as much). Packed it
//! is one instruction, one entry and 17 words (about 100 bytes): issue 23's aim of a
//! program held in at most five times its source.

use std::rc::Rc;

use rapid_sema::types::TypeId;
use rustc_hash::FxHashMap;

use crate::value::{Array, Record, Value};

/// One node of a shape, in pre-order: a record or an array is followed by its parts.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Node {
    /// A record of type `ty`; its `n` components' shapes follow.
    Record { ty: TypeId, n: u16 },
    /// An array of these dimensions (as `Array::dims`) holding `n` elements, all of
    /// the one shape that follows.
    Array { dims: [u32; 3], n: u32 },
    /// A num: one word, its bits.
    Num,
    /// A dnum: two words, its bits (low word first).
    Dnum,
    /// A bool: one word, 0 or 1.
    Bool,
    /// A string: one word, its index among the pool's strings.
    Str,
}

/// The packed constants of one routine.
#[derive(Debug, Clone, Default)]
pub struct Pool {
    /// Every shape's nodes, end to end.
    nodes: Vec<Node>,
    /// Shape `s` is `nodes[shapes[s].0 .. shapes[s].0 + shapes[s].1]`.
    shapes: Vec<(u32, u32)>,
    /// The leaves of every constant, end to end.
    words: Vec<u32>,
    /// Constant `k`: its shape and its first word.
    entries: Vec<(u32, u32)>,
    /// The strings leaves name.
    strings: Vec<Rc<str>>,
}

/// A constant to pack: its shape's nodes and its leaves.
#[derive(Debug, Default)]
pub struct Draft {
    pub nodes: Vec<Node>,
    pub words: Vec<u32>,
}

impl Pool {
    /// How many constants the pool holds.
    pub fn len(&self) -> usize {
        self.entries.len()
    }

    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }

    /// Constant `k`, built anew (records and arrays have value semantics: each use
    /// gets its own).
    pub fn value(&self, k: u32) -> Option<Value> {
        let &(shape, first) = self.entries.get(k as usize)?;
        let &(start, len) = self.shapes.get(shape as usize)?;
        let nodes = self.nodes.get(start as usize..(start + len) as usize)?;
        let mut reader = Reader { pool: self, nodes, node: 0, word: first as usize };
        reader.value()
    }

    /// Appends leaf `value` (a num, dnum, bool or string) to `draft`; `false` for any
    /// other value, which cannot be packed.
    pub fn draft_leaf(&mut self, draft: &mut Draft, value: &Value) -> bool {
        match value {
            Value::Num(n) => {
                draft.nodes.push(Node::Num);
                draft.words.push(n.to_bits());
            }
            Value::Dnum(d) => {
                let bits = d.to_bits();
                draft.nodes.push(Node::Dnum);
                draft.words.extend([bits as u32, (bits >> 32) as u32]);
            }
            Value::Bool(b) => {
                draft.nodes.push(Node::Bool);
                draft.words.push(u32::from(*b));
            }
            Value::Str(s) => {
                draft.nodes.push(Node::Str);
                draft.words.push(self.strings.len() as u32);
                self.strings.push(s.clone());
            }
            _ => return false,
        }
        true
    }

    /// Appends packed constant `k`'s shape and leaves to `draft`.
    pub fn draft_entry(&self, draft: &mut Draft, k: u32) -> bool {
        let Some(&(shape, first)) = self.entries.get(k as usize) else { return false };
        let (start, len) = self.shapes[shape as usize];
        draft.nodes.extend_from_slice(&self.nodes[start as usize..(start + len) as usize]);
        let end = self.entries.get(k as usize + 1).map_or(self.words.len(), |&(_, w)| w as usize);
        draft.words.extend_from_slice(&self.words[first as usize..end]);
        true
    }

    /// Drops the constants from `k` on (the compiler took them back to build a bigger
    /// one). Their shapes and strings stay: others may share them.
    pub fn truncate(&mut self, k: u32) {
        if let Some(&(_, first)) = self.entries.get(k as usize) {
            self.words.truncate(first as usize);
            self.entries.truncate(k as usize);
        }
    }

    /// Adds `draft` as a constant; `shapes` interns shapes (the compiler's own map).
    pub fn add(&mut self, draft: Draft, shapes: &mut FxHashMap<Box<[Node]>, u32>) -> u32 {
        let shape = match shapes.get(draft.nodes.as_slice()) {
            Some(&s) => s,
            None => {
                let s = self.shapes.len() as u32;
                self.shapes.push((self.nodes.len() as u32, draft.nodes.len() as u32));
                self.nodes.extend_from_slice(&draft.nodes);
                shapes.insert(draft.nodes.into_boxed_slice(), s);
                s
            }
        };
        self.entries.push((shape, self.words.len() as u32));
        self.words.extend_from_slice(&draft.words);
        self.entries.len() as u32 - 1
    }

    /// Gives back what the vectors hold beyond their contents (they grew by doubling
    /// while the routine was compiled).
    pub fn shrink_to_fit(&mut self) {
        self.nodes.shrink_to_fit();
        self.shapes.shrink_to_fit();
        self.words.shrink_to_fit();
        self.entries.shrink_to_fit();
        self.strings.shrink_to_fit();
    }
}

/// Builds a value from a shape's nodes and the words of its leaves.
struct Reader<'a> {
    pool: &'a Pool,
    nodes: &'a [Node],
    node: usize,
    word: usize,
}

impl Reader<'_> {
    fn word(&mut self) -> Option<u32> {
        let w = *self.pool.words.get(self.word)?;
        self.word += 1;
        Some(w)
    }

    fn value(&mut self) -> Option<Value> {
        let node = *self.nodes.get(self.node)?;
        self.node += 1;
        Some(match node {
            Node::Num => Value::Num(f32::from_bits(self.word()?)),
            Node::Dnum => {
                let (lo, hi) = (self.word()?, self.word()?);
                Value::Dnum(f64::from_bits(u64::from(lo) | (u64::from(hi) << 32)))
            }
            Node::Bool => Value::Bool(self.word()? != 0),
            Node::Str => Value::Str(self.pool.strings.get(self.word()? as usize)?.clone()),
            Node::Record { ty, n } => {
                let fields = (0..n).map(|_| self.value()).collect::<Option<Vec<_>>>()?;
                Value::Record(Rc::new(Record { ty, fields }))
            }
            Node::Array { dims, n } => {
                // Every element has the shape that follows: read it again for each.
                let element = self.node;
                let mut elems = Vec::with_capacity(n as usize);
                for _ in 0..n {
                    self.node = element;
                    elems.push(self.value()?);
                }
                if n == 0 {
                    self.skip();
                }
                Value::Array(Box::new(Array { dims, elems }))
            }
        })
    }

    /// Steps over one shape without reading words (an empty array's element shape).
    fn skip(&mut self) {
        let Some(&node) = self.nodes.get(self.node) else { return };
        self.node += 1;
        match node {
            Node::Record { n, .. } => (0..n).for_each(|_| self.skip()),
            Node::Array { .. } => self.skip(),
            _ => {}
        }
    }
}

/// What `Instr::MakeRecord` or `Instr::MakeArray` would build from the parts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Whole {
    Record(TypeId),
    Array,
}

/// An aggregate being packed: its parts' shapes and leaves go, in order, into one
/// draft behind a place for its head (no allocation per part).
#[derive(Debug)]
pub struct Builder {
    draft: Draft,
    /// Where each part's nodes start in `draft.nodes`.
    starts: Vec<u32>,
}

impl Builder {
    pub fn with_parts(n: usize) -> Builder {
        // Node 0 is the head's place, written by `finish`.
        Builder { draft: Draft { nodes: vec![Node::Bool], words: Vec::new() }, starts: Vec::with_capacity(n) }
    }

    /// The next part is leaf `value`; `false` when it cannot be packed.
    pub fn leaf(&mut self, pool: &mut Pool, value: &Value) -> bool {
        self.starts.push(self.draft.nodes.len() as u32);
        pool.draft_leaf(&mut self.draft, value)
    }

    /// The next part is packed constant `k`.
    pub fn entry(&mut self, pool: &Pool, k: u32) -> bool {
        self.starts.push(self.draft.nodes.len() as u32);
        pool.draft_entry(&mut self.draft, k)
    }

    /// The draft of the value `whole` builds from the parts, as the instruction would
    /// build it at run time; `None` when it cannot be packed (the instruction is kept).
    /// An array's elements must all have one shape; an array of rows becomes one array
    /// of up to three dimensions (`compile::flatten_array`).
    pub fn finish(self, whole: Whole) -> Option<Draft> {
        let Builder { mut draft, starts } = self;
        let n = u32::try_from(starts.len()).ok()?;
        match whole {
            Whole::Record(ty) => draft.nodes[0] = Node::Record { ty, n: u16::try_from(n).ok()? },
            Whole::Array => {
                let range = |i: usize| starts[i] as usize..starts.get(i + 1).map_or(draft.nodes.len(), |&s| s as usize);
                starts.first()?;
                let first = range(0);
                if (1..starts.len()).any(|i| draft.nodes[range(i)] != draft.nodes[first.clone()]) {
                    return None;
                }
                draft.nodes.truncate(first.end);
                match draft.nodes[1] {
                    // Rows: their elements, one after the other.
                    Node::Array { dims, n: per_row } => {
                        if dims[2] != 0 {
                            return None;
                        }
                        draft.nodes[0] = Node::Array { dims: [n, dims[0], dims[1]], n: n.checked_mul(per_row)? };
                        draft.nodes.remove(1);
                    }
                    _ => draft.nodes[0] = Node::Array { dims: [n, 0, 0], n },
                }
            }
        }
        Some(draft)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pack(pool: &mut Pool, shapes: &mut FxHashMap<Box<[Node]>, u32>, leaves: &[Value], whole: Whole) -> u32 {
        let mut builder = Builder::with_parts(leaves.len());
        for leaf in leaves {
            assert!(builder.leaf(pool, leaf));
        }
        pool.add(builder.finish(whole).expect("packable"), shapes)
    }

    #[test]
    fn a_packed_record_comes_back_as_the_record_it_was() {
        let mut pool = Pool::default();
        let mut shapes = FxHashMap::default();
        let ty = rapid_sema::types::ANY;
        let leaves = [Value::Num(-0.5), Value::Dnum(1e300), Value::Bool(true), Value::Str("ab".into())];
        let k = pack(&mut pool, &mut shapes, &leaves, Whole::Record(ty));
        let expected = Value::Record(Rc::new(Record { ty, fields: leaves.to_vec() }));
        assert_eq!(pool.value(k), Some(expected));
        // A second record of the same shape shares it.
        let k2 = pack(&mut pool, &mut shapes, &leaves, Whole::Record(ty));
        assert_eq!((k, k2), (0, 1));
        assert_eq!(pool.shapes.len(), 1);
        assert_eq!(pool.value(k2), pool.value(k));
    }

    #[test]
    fn a_packed_record_of_records_and_an_array_keep_their_structure() {
        let mut pool = Pool::default();
        let mut shapes = FxHashMap::default();
        let ty = rapid_sema::types::ANY;
        let inner = pack(&mut pool, &mut shapes, &[Value::Num(1.0), Value::Num(2.0)], Whole::Record(ty));
        let mut outer = Builder::with_parts(2);
        assert!(outer.entry(&pool, inner));
        assert!(outer.leaf(&mut pool, &Value::Num(3.0)));
        pool.truncate(inner);
        assert!(pool.is_empty());
        let k = pool.add(outer.finish(Whole::Record(ty)).unwrap(), &mut shapes);
        let pair = Value::Record(Rc::new(Record { ty, fields: vec![Value::Num(1.0), Value::Num(2.0)] }));
        let expected = Value::Record(Rc::new(Record { ty, fields: vec![pair, Value::Num(3.0)] }));
        assert_eq!(pool.value(k), Some(expected));

        let nums = [Value::Num(4.0), Value::Num(5.0), Value::Num(6.0)];
        let a = pack(&mut pool, &mut shapes, &nums, Whole::Array);
        let expected = Value::Array(Box::new(Array { dims: [3, 0, 0], elems: nums.to_vec() }));
        assert_eq!(pool.value(a), Some(expected));
    }

    #[test]
    fn an_array_of_rows_is_one_array_as_make_array_builds_it() {
        let mut pool = Pool::default();
        let mut shapes = FxHashMap::default();
        let rows = [[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]];
        let mut built = Vec::new();
        for row in rows {
            let nums: Vec<Value> = row.iter().map(|&x| Value::Num(x)).collect();
            let k = pack(&mut pool, &mut shapes, &nums, Whole::Array);
            built.push(pool.value(k).expect("a row"));
        }
        let mut whole = Builder::with_parts(2);
        assert!(whole.entry(&pool, 0) && whole.entry(&pool, 1));
        pool.truncate(0);
        let k = pool.add(whole.finish(Whole::Array).expect("rows of one shape"), &mut shapes);
        let expected = crate::compile::flatten_array(Array { dims: [2, 0, 0], elems: built });
        assert_eq!(pool.value(k), Some(expected));
        assert!(matches!(pool.value(k), Some(Value::Array(a)) if a.dims == [2, 3, 0]));
    }

    #[test]
    fn elements_of_different_shapes_are_not_packed() {
        let mut pool = Pool::default();
        let mut mixed = Builder::with_parts(2);
        assert!(mixed.leaf(&mut pool, &Value::Num(1.0)));
        assert!(mixed.leaf(&mut pool, &Value::Str("x".into())));
        assert!(mixed.finish(Whole::Array).is_none());
        assert!(!Builder::with_parts(1).leaf(&mut pool, &Value::Absent));
        assert!(Builder::with_parts(0).finish(Whole::Array).is_none());
    }
}
