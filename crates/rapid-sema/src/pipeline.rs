//! Parsing a long routine body on a second thread while the checker works through it.
//!
//! The parser thread batches body items together with the arena that holds their
//! expressions and sends each batch over a bounded channel; the checker thread checks
//! the batch and sends the emptied arena back for reuse. Both threads see the items
//! in source order, so the diagnostics are exactly those of the one-thread path.

use std::sync::mpsc;

use rapid_syntax::ast::{Arena, BodyItem};
use rapid_syntax::{parse_body, Interner, Span, SyntaxError};

use crate::checker::Checker;

/// Items per batch: large enough that channel traffic is noise, small enough that a
/// batch's arena stays in cache.
const BATCH_ITEMS: usize = 256;
/// Batches in flight; bounds memory at a few batches whatever the body's size.
const BATCHES_IN_FLIGHT: usize = 4;

type Batch = (Vec<BodyItem>, Arena);

/// Parses the body at `body_span` on a scoped thread and checks its items here.
/// Returns the body's syntax errors.
pub(crate) fn check_body(
    ck: &mut Checker<'_>,
    text: &str,
    body_span: Span,
    interner: &mut Interner,
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
                    // The checker only stops listening when it panicked; nothing to do then.
                    let _ = batch_tx.send((batch, full));
                }
            };
            parse_body(text, body_span, interner, Some(&mut sink))
        });
        for (items, mut arena) in batch_rx {
            for item in &items {
                ck.body_item(item, &arena);
            }
            arena.clear();
            let _ = arena_tx.send(arena);
        }
        parser.join().unwrap_or_else(|panic| std::panic::resume_unwind(panic))
    })
}
