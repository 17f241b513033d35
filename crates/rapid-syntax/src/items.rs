//! A routine body's top-level items, handed one at a time to whoever works through them
//! (the checker, the compiler) with the arena that holds their expressions.
//!
//! A long body (a CAM program holds one routine of millions of moves) is parsed on a
//! second thread while the caller works: the parser thread batches items together with
//! their arena and sends each batch over a bounded channel; the caller's thread takes
//! the items and sends the emptied arena back for reuse. Both threads see the items in
//! source order, so the caller sees exactly what the one-thread path gives it.

use std::sync::mpsc;

use crate::ast::{Arena, BodyItem};
use crate::{parse_body, Interner, Span, SyntaxError};

/// Bodies at least this long (in bytes) are parsed on a second thread.
pub const PIPELINE_THRESHOLD: u32 = 1 << 20;
/// Items per batch: large enough that channel traffic is noise, small enough that a
/// batch's arena stays in cache.
const BATCH_ITEMS: usize = 256;
/// Batches in flight; bounds memory at a few batches whatever the body's size.
const BATCHES_IN_FLIGHT: usize = 4;

type Batch = (Vec<BodyItem>, Arena);

/// Parses the body at `body_span` of a routine found by [`crate::parse_outline`] and
/// hands each top-level item (declaration, statement, handler keyword; not the final
/// `BodyItem::End`) to `take`, in source order. Memory stays bounded by a few items
/// whatever the body's length. Returns the body's syntax errors.
pub fn for_each_body_item(
    text: &str,
    body_span: Span,
    interner: &mut Interner,
    mut take: impl FnMut(&BodyItem, &Arena),
) -> Vec<SyntaxError> {
    if body_span.len() >= PIPELINE_THRESHOLD {
        return alongside(text, body_span, interner, take);
    }
    let mut sink = |item: BodyItem, arena: &mut Arena| {
        if !matches!(item, BodyItem::End) {
            take(&item, arena);
        }
        arena.clear();
    };
    parse_body(text, body_span, interner, Some(&mut sink))
}

/// [`for_each_body_item`] with the parser on a scoped thread.
fn alongside(
    text: &str,
    body_span: Span,
    interner: &mut Interner,
    mut take: impl FnMut(&BodyItem, &Arena),
) -> Vec<SyntaxError> {
    let (batch_tx, batch_rx) = mpsc::sync_channel::<Batch>(BATCHES_IN_FLIGHT);
    let (arena_tx, arena_rx) = mpsc::channel::<Arena>();
    std::thread::scope(|scope| {
        let parser = scope.spawn(move || {
            let mut items = Vec::with_capacity(BATCH_ITEMS);
            let mut sink = |item: BodyItem, arena: &mut Arena| {
                let end = matches!(item, BodyItem::End);
                if !end {
                    items.push(item);
                }
                if items.len() >= BATCH_ITEMS || (end && !items.is_empty()) {
                    let recycled = arena_rx.try_recv().unwrap_or_default();
                    let full = std::mem::replace(arena, recycled);
                    let batch = std::mem::replace(&mut items, Vec::with_capacity(BATCH_ITEMS));
                    // The caller only stops listening when it panicked; nothing to do then.
                    let _ = batch_tx.send((batch, full));
                }
            };
            parse_body(text, body_span, interner, Some(&mut sink))
        });
        for (items, mut arena) in batch_rx {
            for item in &items {
                take(item, &arena);
            }
            arena.clear();
            let _ = arena_tx.send(arena);
        }
        parser.join().unwrap_or_else(|panic| std::panic::resume_unwind(panic))
    })
}
