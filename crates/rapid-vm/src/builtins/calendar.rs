//! The controller's calendar clock (§1.14): CDate, CTime, GetTime. It is the wall
//! clock when the program was loaded plus the controller time since, so WaitTime in
//! virtual time moves it as it would move on a real controller. The host's time
//! zone is not read (std has no time-zone database): dates and times are UTC.

use super::{present, Ctx};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::Value;

/// The built-ins this family runs (see `registry.rs`).
pub(super) static FAMILY: super::Family = super::Family {
    file: file!(),
    builtins: &[super::native("CDate", c_date), super::native("CTime", c_time), super::native("GetTime", get_time)],
};

type Res = Result<Option<Value>, RapidError>;

/// A moment split into calendar fields (UTC).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Civil {
    pub year: i64,
    pub month: u32,
    pub day: u32,
    pub hour: u32,
    pub minute: u32,
    pub second: u32,
    /// 1 = Monday … 7 = Sunday, as GetTime \WDay counts.
    pub weekday: u32,
}

/// Splits seconds since 1970-01-01 00:00 UTC into calendar fields (proleptic
/// Gregorian calendar, days counted from 0000-03-01 so leap days end each year).
pub(super) fn civil_from_unix(seconds: i64) -> Civil {
    let days = seconds.div_euclid(86_400);
    let in_day = seconds.rem_euclid(86_400) as u32;
    // 1970-01-01 was a Thursday (4).
    let weekday = ((days + 3).rem_euclid(7) + 1) as u32;
    let shifted = days + 719_468; // days from 0000-03-01 to 1970-01-01
    let era = shifted.div_euclid(146_097);
    let day_of_era = shifted.rem_euclid(146_097);
    let year_of_era = (day_of_era - day_of_era / 1460 + day_of_era / 36_524 - day_of_era / 146_096) / 365;
    let day_of_year = day_of_era - (365 * year_of_era + year_of_era / 4 - year_of_era / 100);
    let month_from_march = (5 * day_of_year + 2) / 153;
    let day = (day_of_year - (153 * month_from_march + 2) / 5 + 1) as u32;
    let month = if month_from_march < 10 { month_from_march + 3 } else { month_from_march - 9 } as u32;
    let year = year_of_era + era * 400 + i64::from(month <= 2);
    Civil { year, month, day, hour: in_day / 3600, minute: in_day / 60 % 60, second: in_day % 60, weekday }
}

fn now(ctx: &Ctx<'_>) -> Civil {
    civil_from_unix((ctx.wall_epoch + ctx.time).floor() as i64)
}

/// `CDate()`: "YYYY-MM-DD".
pub(super) fn c_date(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    let t = now(ctx);
    Ok(Some(Value::Str(format!("{:04}-{:02}-{:02}", t.year, t.month, t.day).into())))
}

/// `CTime()`: "HH:MM:SS".
pub(super) fn c_time(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    let t = now(ctx);
    Ok(Some(Value::Str(format!("{:02}:{:02}:{:02}", t.hour, t.minute, t.second).into())))
}

/// `GetTime(\WDay | \Hour | \Min | \Sec)`: one field of the current time. One switch
/// is required; without one the call is an argument error.
pub(super) fn get_time(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let t = now(ctx);
    let fields = [t.weekday, t.hour, t.minute, t.second];
    let Some(field) = (0..4).find(|&i| present(args.get(i))) else {
        return Err(ctx.error(Err::ArgValue, "GetTime needs one of \\WDay, \\Hour, \\Min, \\Sec"));
    };
    Ok(Some(Value::Num(fields[field] as f32)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_epoch_is_a_thursday_in_1970() {
        let t = civil_from_unix(0);
        assert_eq!((t.year, t.month, t.day, t.hour, t.weekday), (1970, 1, 1, 0, 4));
    }

    #[test]
    fn a_known_moment_splits_into_its_fields() {
        // 1_700_000_000 s is 2023-11-14 22:13:20 UTC, a Tuesday.
        let t = civil_from_unix(1_700_000_000);
        assert_eq!((t.year, t.month, t.day), (2023, 11, 14));
        assert_eq!((t.hour, t.minute, t.second, t.weekday), (22, 13, 20, 2));
    }

    #[test]
    fn leap_days_and_century_rules() {
        // 2000-02-29 (a leap day in a year divisible by 400) is 951_782_400 s.
        let t = civil_from_unix(951_782_400);
        assert_eq!((t.year, t.month, t.day, t.weekday), (2000, 2, 29, 2));
        // One day before 1970: 1969-12-31, a Wednesday.
        let t = civil_from_unix(-86_400);
        assert_eq!((t.year, t.month, t.day, t.weekday), (1969, 12, 31, 3));
    }
}
