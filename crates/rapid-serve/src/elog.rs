//! The event log as RWS shows it (`/rw/elog/{domain}`): one controller-wide list,
//! newest first, numbered by one sequence (RWS's `seqnum`, the last part of each
//! entry's `/rw/elog/0/{seq}`), each entry stamped with the wall-clock time the server
//! saw it. It gathers every task's log (ErrWrite, ErrLog, the system error handler)
//! and adds the panel's own state changes (motors on/off) the way RobotWare logs them.
//!
//! The log is never empty: it starts with the motors' state at boot (the
//! motion-program client indexes `log[0]` before it starts a program).

use std::collections::VecDeque;
use std::time::{SystemTime, UNIX_EPOCH};

use rapid_controller::api::Session;
use rapid_vm::events::EventKind;

/// Entries kept, oldest dropped first.
// uncertain: RobotWare keeps a bounded number per domain; its size is not public.
const CAPACITY: usize = 1000;

/// One entry.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Entry {
    pub(crate) seq: u64,
    /// 1 information, 2 warning, 3 error.
    pub(crate) msgtype: u8,
    /// Domain × 10000 + number.
    pub(crate) code: u32,
    /// `YYYY-MM-DD T HH:MM:SS`, UTC.
    pub(crate) tstamp: String,
    pub(crate) title: String,
    /// The arguments: the title, then each message line (ErrWrite's Reason, RL2..RL4).
    pub(crate) args: Vec<String>,
    pub(crate) source: String,
}

/// The log and where each task's log was read up to.
#[derive(Debug, Default)]
pub(crate) struct Elog {
    entries: VecDeque<Entry>,
    next_seq: u64,
    /// By task index: the VM sequence number of the next entry to take.
    taken: Vec<u64>,
}

impl Elog {
    /// The first entry: the motors' state at power on.
    pub(crate) fn boot(&mut self, motors_on: bool) {
        self.motors(motors_on);
    }

    /// The motors went on or off.
    // uncertain: codes and titles as we remember RobotWare 6's operational log.
    pub(crate) fn motors(&mut self, on: bool) {
        let (code, title) = if on { (10011, "Motors ON state") } else { (10012, "Motors OFF state") };
        self.push(1, code, title.to_owned(), vec![], "panel".to_owned());
    }

    fn push(&mut self, msgtype: u8, code: u32, title: String, args: Vec<String>, source: String) -> u64 {
        self.next_seq += 1;
        let seq = self.next_seq;
        if self.entries.len() >= CAPACITY {
            self.entries.pop_front();
        }
        self.entries.push_back(Entry { seq, msgtype, code, tstamp: timestamp(SystemTime::now()), title, args, source });
        seq
    }

    /// Takes the tasks' new entries (in controller-time order); returns their numbers.
    pub(crate) fn refresh(&mut self, session: &Session) -> Vec<u64> {
        let tasks = session.tasks();
        self.taken.resize(tasks.len(), 0);
        let mut fresh = Vec::new();
        for (idx, task) in session.controller().tasks.iter().enumerate() {
            let log = task.loaded.vm.event_log();
            let from = log.partition_point(|e| e.seq < self.taken[idx]);
            for event in &log[from..] {
                fresh.push((event.time, idx, event.clone()));
            }
            if let Some(last) = log.last() {
                self.taken[idx] = last.seq + 1;
            }
        }
        fresh.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        let mut numbers = Vec::new();
        for (_, idx, event) in fresh {
            let msgtype = match event.kind {
                EventKind::Info => 1,
                EventKind::Warning => 2,
                EventKind::Error => 3,
            };
            let mut args = vec![event.title.clone()];
            args.extend(event.details.iter().chain(&event.lines).cloned());
            let source = tasks.get(idx).map_or_else(String::new, |t| t.name.clone());
            numbers.push(self.push(msgtype, event.code(), event.title.clone(), args, source));
        }
        numbers
    }

    /// The entries of `domain` (0: all), newest first.
    pub(crate) fn newest_first(&self, domain: u32) -> impl Iterator<Item = &Entry> {
        self.entries.iter().rev().filter(move |e| domain == 0 || e.code / 10_000 == domain)
    }

    pub(crate) fn get(&self, seq: u64) -> Option<&Entry> {
        self.entries.iter().find(|e| e.seq == seq)
    }

    /// Empties a domain (0: all).
    pub(crate) fn clear(&mut self, domain: u32) {
        self.entries.retain(|e| domain != 0 && e.code / 10_000 != domain);
    }
}

/// `YYYY-MM-DD T HH:MM:SS` in UTC, as RWS writes an event's time.
pub(crate) fn timestamp(time: SystemTime) -> String {
    let secs = time.duration_since(UNIX_EPOCH).map_or(0, |d| d.as_secs());
    let (days, rest) = (secs / 86_400, secs % 86_400);
    let (y, m, d) = civil_from_days(days as i64);
    format!("{y:04}-{m:02}-{d:02} T {:02}:{:02}:{:02}", rest / 3600, rest % 3600 / 60, rest % 60)
}

/// The Gregorian date of a day count since 1970-01-01 (H. Hinnant's algorithm).
fn civil_from_days(days: i64) -> (i64, u32, u32) {
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let m = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    let y = yoe + era * 400 + i64::from(m <= 2);
    (y, m, d)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn timestamps_are_utc_dates() {
        assert_eq!(timestamp(UNIX_EPOCH), "1970-01-01 T 00:00:00");
        // 2014-06-23 10:00:51 UTC, the example in the RWS manual.
        let t = UNIX_EPOCH + std::time::Duration::from_secs(1_403_517_651);
        assert_eq!(timestamp(t), "2014-06-23 T 10:00:51");
        // A leap day.
        let t = UNIX_EPOCH + std::time::Duration::from_secs(951_782_400);
        assert_eq!(timestamp(t), "2000-02-29 T 00:00:00");
    }

    #[test]
    fn the_log_is_numbered_newest_first_and_never_starts_empty() {
        let mut log = Elog::default();
        log.boot(true);
        log.motors(false);
        let seqs: Vec<u64> = log.newest_first(0).map(|e| e.seq).collect();
        assert_eq!(seqs, vec![2, 1]);
        assert_eq!(log.newest_first(1).count(), 2);
        assert_eq!(log.newest_first(8).count(), 0);
        assert_eq!(log.get(2).map(|e| e.code), Some(10012));
    }
}
