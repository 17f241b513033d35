//! The page: the template with its styles, script, the run's facts as text (title,
//! summary, the table of moves, rendered here so they read without the script) and
//! the data the script draws.

use std::fmt::Write as _;

use super::data::{Data, MAX_MOVES};
use crate::motion_out::RunOutputs;

const TEMPLATE: &str = include_str!("page.html");
const STYLE: &str = include_str!("report.css");
const SCRIPT: &str = include_str!("report.js");

/// The whole page.
pub(super) fn page(out: &RunOutputs<'_>, places: &[String], data: &Data) -> anyhow::Result<String> {
    let json = serde_json::to_string(data)?;
    let title = format!("{} — run report", out.program);
    let mut page = String::with_capacity(TEMPLATE.len() + STYLE.len() + SCRIPT.len() + json.len() + 4096);
    fill(&mut page, TEMPLATE, |name, page| match name {
        "TITLE" => page.push_str(&escape(&title)),
        "STYLE" => page.push_str(STYLE),
        "SCRIPT" => page.push_str(SCRIPT),
        "SUMMARY" => summary(page, out),
        "MOVES" => moves_table(page, out, places),
        // Inside <script type="application/json">: no `<` may end the element early,
        // and `\u003c` reads back as `<` in JSON strings.
        "DATA" => page.push_str(&json.replace('<', "\\u003c")),
        _ => {}
    });
    Ok(page)
}

/// Copies `template` to `page`, each `{{NAME}}` replaced by what `put` writes; one
/// pass, so nothing substituted is searched again.
fn fill(page: &mut String, template: &str, mut put: impl FnMut(&str, &mut String)) {
    let mut rest = template;
    while let Some(open) = rest.find("{{") {
        page.push_str(&rest[..open]);
        let after = &rest[open + 2..];
        let Some(close) = after.find("}}") else {
            rest = &rest[open..];
            break;
        };
        put(&after[..close], page);
        rest = &after[close + 2..];
    }
    page.push_str(rest);
}

/// Text for HTML: the five characters that could end or open markup escaped.
pub(super) fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}

/// The facts at the top of the page: program, task, robot, cycle time, moves.
fn summary(page: &mut String, out: &RunOutputs<'_>) {
    let robot = out.robot;
    let failures = robot.recorded_facts.iter().filter(|f| f.corner_path_failure).count();
    let items = [
        ("Program", escape(&out.program)),
        ("Task", escape(out.task)),
        // The robot's mechanical unit (ROB_n) and its model.
        ("Robot", format!("{} ({})", escape(out.robot_name.unwrap_or("none")), escape(robot.model.name))),
        ("Cycle time", format!("{:.3} s", out.cycle)),
        ("Moves", robot.recorded_facts.len().to_string()),
        ("Corner path failures", failures.to_string()),
    ];
    for (label, value) in items {
        let class = if label == "Corner path failures" && failures > 0 { " class=\"bad\"" } else { "" };
        let _ = write!(page, "<div><dt>{label}</dt><dd{class}>{value}</dd></div>");
    }
}

/// What a corner blended while the TCP stood, for the table of moves.
fn standing_corner(kind: Option<rapid_motion::plan::CornerKind>) -> Option<&'static str> {
    match kind? {
        rapid_motion::plan::CornerKind::Orientation => Some("orientation"),
        rapid_motion::plan::CornerKind::ExternalAxes => Some("external axes"),
        _ => None,
    }
}

/// The table of moves: one row per move (at most [`MAX_MOVES`], with a note when cut).
fn moves_table(page: &mut String, out: &RunOutputs<'_>, places: &[String]) {
    let facts = &out.robot.recorded_facts;
    for (i, f) in facts.iter().enumerate().take(MAX_MOVES) {
        let place = places.get(i).map_or("", String::as_str);
        let zone = if f.fine {
            "fine".to_string()
        } else if let Some(what) = standing_corner(f.corner) {
            // The TCP stood: the corner was not in its position zone.
            format!("z {} mm ({what} corner)", trim(f.zone))
        } else if (f.zone_used - f.zone).abs() > 0.05 {
            format!("z {} mm (used {:.1})", trim(f.zone), f.zone_used)
        } else {
            format!("z {} mm", trim(f.zone))
        };
        let (cpf, class) = if f.corner_path_failure { ("yes", " class=\"bad\"") } else { ("", "") };
        let _ = writeln!(
            page,
            "<tr class=\"move\" data-move=\"{i}\"><td>{}</td><td>{}</td><td class=\"place\">{}</td>\
             <td>{:.3}</td><td>{:.3}</td><td>{:.3}</td><td>{zone}</td><td{class}>{cpf}</td></tr>",
            i + 1,
            escape(if f.instruction.is_empty() { "?" } else { f.instruction }),
            escape(place),
            f.start,
            f.end,
            f.end - f.start,
        );
    }
    if facts.len() > MAX_MOVES {
        let _ = write!(
            page,
            "<tr class=\"note\"><td colspan=\"8\">… {} more moves not listed (the page lists the first {MAX_MOVES})</td></tr>",
            facts.len() - MAX_MOVES
        );
    }
}

/// A zone size without needless decimals (`50`, `0.3`).
fn trim(x: f64) -> String {
    let text = format!("{x:.2}");
    text.trim_end_matches('0').trim_end_matches('.').to_string()
}

#[cfg(test)]
mod tests {
    #[test]
    fn fill_replaces_each_placeholder_once() {
        let mut page = String::new();
        super::fill(&mut page, "a{{X}}b{{Y}}c{{", |name, page| page.push_str(if name == "X" { "{{Y}}" } else { "2" }));
        assert_eq!(page, "a{{Y}}b2c{{");
    }

    #[test]
    fn escape_covers_markup() {
        assert_eq!(super::escape("<a href=\"x\">&'"), "&lt;a href=&quot;x&quot;&gt;&amp;&#39;");
    }
}
