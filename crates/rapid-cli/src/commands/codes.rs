//! `rapid codes`: the table of diagnostic codes.

use std::io::{self, BufWriter, Write};

use rapid_sema::Code;

use crate::commands::ExitStatus;
use crate::render::severity_name;

pub(crate) fn run() -> anyhow::Result<ExitStatus> {
    let mut out = BufWriter::new(io::stdout().lock());
    write_table(&mut out)?;
    out.flush()?;
    Ok(ExitStatus::Success)
}

fn write_table(out: &mut dyn Write) -> io::Result<()> {
    writeln!(out, "{:<6} {:<8} summary", "code", "severity")?;
    for code in Code::ALL {
        let severity = severity_name(code.severity());
        writeln!(out, "{:<6} {:<8} {}", code.as_str(), severity, code.summary())?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_has_a_line_per_code() {
        let mut out = Vec::new();
        write_table(&mut out).unwrap();
        let text = String::from_utf8(out).unwrap();
        assert_eq!(text.lines().count(), Code::ALL.len() + 1);
        assert!(text.contains("E0130  error    a .pgf program file entry"));
    }
}
