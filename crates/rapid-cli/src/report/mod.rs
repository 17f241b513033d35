//! `rapid run --report FILE.html`: one self-contained page of a run that a robot
//! programmer can look at instead of reading a trace: the TCP path in 3D coloured by
//! speed with the programmed points and their zones, the axes' positions and speeds
//! against time with the model's limits, the I/O timeline and the table of moves.
//!
//! The page is made of three assets compiled into the binary (`page.html`,
//! `report.css`, `report.js`: hand-written canvas drawing, no library, no network)
//! and the run's data as JSON ([`data`]). It holds no date, so the same run gives the
//! same bytes. What each view shows: docs/report.md.

mod data;
mod html;

use std::path::Path;

use crate::motion_out::RunOutputs;

/// Writes the report page of a run, atomically.
pub(crate) fn write(path: &Path, out: &RunOutputs<'_>, places: &[String]) -> anyhow::Result<()> {
    let data = data::collect(out);
    let page = html::page(out, places, &data)?;
    crate::save::write_new(path, page.as_bytes())
}
