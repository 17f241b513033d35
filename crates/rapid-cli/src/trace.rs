//! `--trace FILE`: the recorded trajectory sampled every `--sample` ms, as CSV or (for a
//! `.json` path) JSON (the format: docs/trace.md), written atomically.
//!
//! A long trace is cut into pieces of consecutive rows that worker threads render at
//! once while this thread writes them in order. Each piece starts from the facts cursor
//! and external axes the rows before it left, found by a cheap first pass over the
//! sample times, so the file is byte for byte the one a single pass writes.

use std::io::Write as _;
use std::path::Path;
use std::sync::mpsc;

use rapid_motion::plan::PlannedMove;
use rapid_robot::robot::RobotState;

use crate::motion_out::{FactsCursor, Point};

/// Most trace rows written (a day at 4 ms): a bound on a mistaken `--sample`.
const MAX_TRACE_ROWS: u64 = 21_600_000;
/// Rows per piece: enough that handing pieces around is noise, few enough that the
/// pieces in flight stay a few megabytes.
const PIECE_ROWS: u64 = 8192;
/// Worker threads at most, however many cores there are.
const MAX_WORKERS: usize = 4;

/// How rows are spelled.
struct Style {
    json: bool,
    time_decimals: u32,
    /// Each move's `path:line`, quoted for the format.
    places: Vec<String>,
    /// The place of a row outside every move.
    empty: String,
    /// The external axes' columns: (extjoint index, name).
    ext: Vec<(usize, String)>,
    /// The arm's columns are written (a positioner's task has no arm: time, its axes
    /// and the line only).
    arm: bool,
    step: f64,
}

/// Consecutive rows: `rows` of them from sample `sample_at` of move `move_at`, the
/// first numbered `row`, with the facts cursor and external axes as the rows before
/// left them.
struct Piece<'a> {
    move_at: usize,
    sample_at: u64,
    rows: u64,
    row: u64,
    cursor: FactsCursor<'a>,
    eax: [f64; 6],
}

/// Writes the trajectory sampled every `sample_ms` to `path`: of robot `robot_name`
/// (`ROB_n`), or without the arm's columns for a task that moves external units only
/// (`None`).
pub(crate) fn write(
    robot: &RobotState,
    places: &[String],
    path: &Path,
    sample_ms: f64,
    robot_name: Option<&str>,
) -> anyhow::Result<()> {
    let arm = robot_name.is_some();
    if !(sample_ms.is_finite() && sample_ms >= 0.1) {
        anyhow::bail!("--sample must be at least 0.1 ms");
    }
    let json = path.extension().is_some_and(|e| e.eq_ignore_ascii_case("json"));
    let ext = external_columns(robot);
    let columns = trace_columns(&ext, arm);
    let traced = if arm { robot.model.name } else { "none" };
    let head = if json {
        json_head((traced, robot_name.unwrap_or_default()), sample_ms, &columns)
    } else {
        columns.join(",") + "\n"
    };
    let style = Style {
        json,
        // Milliseconds while the period is whole milliseconds, else tenths of them.
        time_decimals: if sample_ms.fract() == 0.0 { 3 } else { 4 },
        places: places.iter().map(|p| if json { json_string(p) } else { csv_field(p) }).collect(),
        empty: if json { "\"\"".to_string() } else { String::new() },
        ext,
        arm,
        step: sample_ms / 1000.0,
    };
    let pieces = cut(robot, style.step);
    crate::save::write_new_with(path, |file| {
        file.write_all(head.as_bytes())?;
        render_in_order(&pieces, |piece| render(robot, &style, piece), |text| file.write_all(text))?;
        if json {
            file.write_all(b"\n]}\n")?;
        }
        Ok(())
    })
}

/// The first pass: the rows cut into pieces, each with the state the rows before it
/// leave (where the facts cursor is, where the external axes were last seen).
fn cut(robot: &RobotState, step: f64) -> Vec<Piece<'_>> {
    let moves: &[PlannedMove] = robot.recorded.as_deref().unwrap_or(&[]);
    let mut cursor = FactsCursor::new(&robot.recorded_facts);
    let mut eax = robot.external.start();
    let mut pieces: Vec<Piece<'_>> = Vec::new();
    let mut row = 0;
    'moves: for (move_at, planned) in moves.iter().enumerate() {
        for k in 0..planned.sample_count(step) {
            if row >= MAX_TRACE_ROWS {
                break 'moves;
            }
            if pieces.last().is_none_or(|p| p.rows >= PIECE_ROWS) {
                let cursor = cursor.clone();
                pieces.push(Piece { move_at, sample_at: k, rows: 0, row, cursor, eax });
            }
            let t = planned.sample_time(step, k);
            cursor.advance(t);
            eax = next_eax(robot, planned, eax, t);
            if let Some(piece) = pieces.last_mut() {
                piece.rows += 1;
            }
            row += 1;
        }
    }
    pieces
}

/// Where the external axes are at `t`, given where they were last seen: a pause of
/// the path keeps them there; an axis in independent mode is where its own motion took it.
fn next_eax(robot: &RobotState, planned: &PlannedMove, last: [f64; 6], t: f64) -> [f64; 6] {
    let mut eax = planned.eax_at(t).unwrap_or(last);
    robot.independent.apply_eax(&mut eax, t);
    eax
}

/// The text of one piece's rows.
fn render(robot: &RobotState, style: &Style, piece: &Piece<'_>) -> Vec<u8> {
    let moves: &[PlannedMove] = robot.recorded.as_deref().unwrap_or(&[]);
    // Room for every row at once: a buffer that grows copies the rows written so far.
    // About 14 bytes a number and a place like `module.mod:123456`.
    let row_bytes = 14 * (TRACE_COLUMNS.len() + style.ext.len()) + 32;
    let mut out = Vec::with_capacity(piece.rows as usize * row_bytes);
    let mut cursor = piece.cursor.clone();
    let mut eax = piece.eax;
    let mut row = piece.row;
    let mut left = piece.rows;
    let mut first = piece.sample_at;
    for planned in moves.get(piece.move_at..).unwrap_or(&[]) {
        if left == 0 {
            break;
        }
        let n = planned.sample_count(style.step).saturating_sub(first).min(left);
        let mount = planned.tool();
        for sample in planned.samples_in(&robot.kin, style.step, first..first + n) {
            // A move made with `\Corr` is where its path correction put it; an axis in
            // independent mode where its own motion took it.
            let carry = robot.carry_at(planned, sample.time);
            let sample = robot.tracked(planned, robot.corrected(planned, sample));
            let sample = robot.with_independent(sample, &mount);
            let point = cursor.locate(sample, carry);
            eax = next_eax(robot, planned, eax, sample.time);
            push_row(&mut out, style, &point, &eax, row);
            row += 1;
        }
        left -= n;
        first = 0;
    }
    out
}

/// One row of the trace, numbered `row`.
fn push_row(out: &mut Vec<u8>, style: &Style, point: &Point, eax: &[f64; 6], row: u64) {
    let json = style.json;
    if json {
        out.extend_from_slice(if row == 0 { b"\n[" } else { b",\n[" });
    }
    let numbers = row_numbers(point, style.time_decimals);
    let shown = if style.arm { &numbers[..] } else { &numbers[..1] };
    for &(value, decimals) in shown {
        push_number(out, value, decimals, json);
        out.push(b',');
    }
    for &(j, _) in &style.ext {
        push_number(out, eax[j], 3, json);
        out.push(b',');
    }
    out.extend_from_slice(point.facts.and_then(|i| style.places.get(i)).unwrap_or(&style.empty).as_bytes());
    out.extend_from_slice(if json { b"]" } else { b"\n" });
}

/// Renders every piece, on worker threads when the machine has more than one core,
/// and hands their texts to `sink` in order. Each worker keeps at most one finished
/// piece waiting, so memory stays bounded whatever the trace's length.
fn render_in_order<P: Sync>(
    pieces: &[P],
    render: impl Fn(&P) -> Vec<u8> + Sync,
    mut sink: impl FnMut(&[u8]) -> std::io::Result<()>,
) -> std::io::Result<()> {
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let workers = cores.clamp(1, MAX_WORKERS).min(pieces.len());
    if workers <= 1 {
        return pieces.iter().try_for_each(|piece| sink(&render(piece)));
    }
    std::thread::scope(|scope| {
        let render = &render;
        let texts: Vec<mpsc::Receiver<Vec<u8>>> = (0..workers)
            .map(|w| {
                let (tx, rx) = mpsc::sync_channel(1);
                scope.spawn(move || {
                    for piece in pieces.iter().skip(w).step_by(workers) {
                        // The writer stopped listening (it failed): nothing more to do.
                        if tx.send(render(piece)).is_err() {
                            return;
                        }
                    }
                });
                rx
            })
            .collect();
        for i in 0..pieces.len() {
            // A worker that hung up early panicked; the scope passes its panic on.
            let Ok(text) = texts[i % workers].recv() else { break };
            sink(&text)?;
        }
        Ok(())
    })
}

/// The trace's columns, in order.
pub(crate) const TRACE_COLUMNS: [&str; 23] = [
    "time",
    "j1",
    "j2",
    "j3",
    "j4",
    "j5",
    "j6",
    "x",
    "y",
    "z",
    "q1",
    "q2",
    "q3",
    "q4",
    "wx",
    "wy",
    "wz",
    "wq1",
    "wq2",
    "wq3",
    "wq4",
    "tcp_speed",
    "line",
];

/// The numbers of a trace row with their decimals (all columns but `line`).
fn row_numbers(p: &Point, time_decimals: u32) -> [(f64, u32); 22] {
    let s = &p.sample;
    let w = p.world.translation.vector;
    let o = p.object.translation.vector;
    let [q1, q2, q3, q4] = rapid_motion::pose::orient(&p.world);
    let [r1, r2, r3, r4] = rapid_motion::pose::orient(&p.object);
    [
        (s.time, time_decimals),
        (s.joints[0], 4),
        (s.joints[1], 4),
        (s.joints[2], 4),
        (s.joints[3], 4),
        (s.joints[4], 4),
        (s.joints[5], 4),
        (w.x, 3),
        (w.y, 3),
        (w.z, 3),
        (q1, 6),
        (q2, 6),
        (q3, 6),
        (q4, 6),
        (o.x, 3),
        (o.y, 3),
        (o.z, 3),
        (r1, 6),
        (r2, 6),
        (r3, 6),
        (r4, 6),
        (s.tcp_speed, 2),
    ]
}

/// The external axes the trace shows after `tcp_speed`: (extjoint index, column name),
/// in `eax_a` … `eax_f` order.
fn external_columns(robot: &RobotState) -> Vec<(usize, String)> {
    let mut axes: Vec<(usize, String)> = robot
        .external
        .units
        .iter()
        .flat_map(|u| &u.unit.axes)
        .map(|a| (a.index(), format!("eax_{}", char::from(b'a' + a.index() as u8))))
        .collect();
    axes.sort();
    axes
}

/// The trace's columns: [`TRACE_COLUMNS`] with the external axes before `line`; of the
/// arm's only `time` without it.
fn trace_columns(ext: &[(usize, String)], arm: bool) -> Vec<String> {
    let (line, numbers) = TRACE_COLUMNS.split_last().expect("the columns end in line");
    let numbers = if arm { numbers } else { &numbers[..1] };
    numbers
        .iter()
        .map(|c| c.to_string())
        .chain(ext.iter().map(|(_, name)| name.clone()))
        .chain([line.to_string()])
        .collect()
}

/// The JSON trace up to its first row: what was traced, and the columns.
fn json_head((robot, mech_unit): (&str, &str), sample_ms: f64, columns: &[String]) -> String {
    let columns: Vec<String> = columns.iter().map(|c| json_string(c)).collect();
    format!(
        "{{\"robot\":{},\"mech_unit\":{},\"sample_ms\":{},\"columns\":[{}],\"rows\":[",
        json_string(robot),
        json_string(mech_unit),
        serde_json::Number::from_f64(sample_ms).map_or("4".into(), |n| n.to_string()),
        columns.join(",")
    )
}

/// A number for the trace: fixed decimals; in JSON a value that is not a number is
/// `null` (JSON has no NaN).
fn push_number(out: &mut Vec<u8>, value: f64, decimals: u32, json: bool) {
    if json && !value.is_finite() {
        out.extend_from_slice(b"null");
    } else {
        push_fixed(out, value, decimals);
    }
}

/// `text` as a JSON string literal.
fn json_string(text: &str) -> String {
    serde_json::to_string(text).unwrap_or_else(|_| "\"\"".into())
}

/// `text` as a CSV field: quoted when it holds a comma, a quote or a line break.
fn csv_field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}

/// `x` with `decimals` decimals, rounded, without a minus sign on zero: integer
/// arithmetic, which is many times faster than the standard exact formatting for the
/// millions of numbers of a long trace.
fn push_fixed(out: &mut Vec<u8>, x: f64, decimals: u32) {
    let scale = 10u64.pow(decimals);
    let scaled = (x * scale as f64).round();
    if !scaled.is_finite() || scaled.abs() >= 9.0e15 {
        let _ = write!(out, "{x:.prec$}", prec = decimals as usize);
        return;
    }
    let n = scaled as i64;
    if n < 0 {
        out.push(b'-');
    }
    // Digits written by hand, least significant first into a buffer: the standard
    // integer formatting costs more than the rest of a trace row.
    let mut n = n.unsigned_abs();
    let mut digits = [0u8; 24];
    let mut at = digits.len();
    for _ in 0..decimals {
        at -= 1;
        digits[at] = b'0' + (n % 10) as u8;
        n /= 10;
    }
    if decimals > 0 {
        at -= 1;
        digits[at] = b'.';
    }
    loop {
        at -= 1;
        digits[at] = b'0' + (n % 10) as u8;
        n /= 10;
        if n == 0 {
            break;
        }
    }
    out.extend_from_slice(&digits[at..]);
}

#[cfg(test)]
mod tests {
    #[test]
    fn fixed_decimals_round_and_keep_zero_unsigned() {
        let mut out = Vec::new();
        for (x, d) in [(1.23456, 3), (-0.00004, 4), (-2.5, 2), (374.0, 3), (0.123456789, 6), (12.0, 0)] {
            super::push_fixed(&mut out, x, d);
            out.push(b' ');
        }
        assert_eq!(String::from_utf8_lossy(&out), "1.235 0.0000 -2.50 374.000 0.123457 12 ");
    }

    /// Pieces rendered on several threads reach the file in their own order, each once.
    #[test]
    fn pieces_arrive_in_order() {
        let pieces: Vec<u32> = (0..101).collect();
        let mut got = Vec::new();
        let render = |n: &u32| {
            // Uneven work, so workers finish out of turn.
            let spin = (n % 7) * 20_000;
            let sum = (0..spin).fold(0u32, |a, b| a.wrapping_add(b));
            format!("{n}:{},", sum % 2).into_bytes()
        };
        super::render_in_order(&pieces, render, |text| {
            got.extend_from_slice(text);
            Ok(())
        })
        .unwrap();
        let text = String::from_utf8(got).unwrap();
        let order: Vec<u32> =
            text.split(',').filter(|t| !t.is_empty()).map(|t| t.split(':').next().unwrap().parse().unwrap()).collect();
        assert_eq!(order, pieces);
    }

    /// A failing write stops the rendering and is reported, without hanging the workers.
    #[test]
    fn a_failed_write_stops_the_pieces() {
        let pieces: Vec<u32> = (0..50).collect();
        let mut written = 0;
        let result = super::render_in_order(
            &pieces,
            |n| vec![*n as u8],
            |_| {
                written += 1;
                if written == 3 {
                    Err(std::io::Error::other("disk full"))
                } else {
                    Ok(())
                }
            },
        );
        assert_eq!(result.unwrap_err().to_string(), "disk full");
        assert_eq!(written, 3);
    }
}
