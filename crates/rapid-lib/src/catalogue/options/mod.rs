//! The catalogue of ABB software options: the data types, data and routines a
//! controller has only when the option is installed. One file per option family.
//!
//! An option's names are known to `rapid check` when the system has the option (its
//! backup's `system.xml` or BACKINFO, or a manifest's `options = [...]`), and when
//! nothing says what the system has (a loose module: the user checking it cannot say
//! what the target controller has installed, so every option is assumed present).
//! On a system that lacks the option they are "belongs to option X, which this
//! system does not have". `rapid run` simulates none of these routines: a program
//! that calls one is refused when it is loaded, with the option's name.

use super::entry::Entry;

mod arc;
mod bullseye;
mod egm;
mod force;
mod production_manager;
mod smartac;

/// One software option: how controllers name it and what it declares.
#[derive(Debug)]
pub struct SoftwareOption {
    /// The short name users and manifests use (`EGM`, `Arc`).
    pub short: &'static str,
    /// The name the manuals and messages use.
    pub name: &'static str,
    /// The catalogue chapter its entries are listed under: its file, `options/egm`
    /// (`docs/builtins.md`).
    pub chapter: &'static str,
    /// ABB's option numbers (the `689` of `689-1 Externally Guided Motion (EGM)`).
    pub numbers: &'static [&'static str],
    /// Words that name the option inside a product description (compared without case).
    pub words: &'static [&'static str],
    pub entries: &'static [Entry],
}

/// Every option the catalogue declares.
pub static ALL_OPTIONS: &[SoftwareOption] = &[
    SoftwareOption {
        short: "Arc",
        name: "Arc (RobotWare Arc)",
        chapter: "options/arc",
        numbers: &["633"],
        words: &["RobotWare Arc"],
        entries: arc::ENTRIES,
    },
    SoftwareOption {
        short: "EGM",
        name: "Externally Guided Motion (EGM)",
        chapter: "options/egm",
        numbers: &["689", "3124"],
        words: &["Externally Guided Motion"],
        entries: egm::ENTRIES,
    },
    SoftwareOption {
        short: "BullsEye",
        name: "BullsEye",
        chapter: "options/bullseye",
        numbers: &["652"],
        words: &["BullsEye"],
        entries: bullseye::ENTRIES,
    },
    SoftwareOption {
        short: "SmarTac",
        name: "SmarTac",
        chapter: "options/smartac",
        // `657-1 SmarTac IO version` in public backups' system.xml.
        numbers: &["657"],
        words: &["SmarTac"],
        entries: smartac::ENTRIES,
    },
    SoftwareOption {
        short: "ForceControl",
        name: "Force Control",
        chapter: "options/force",
        numbers: &["661"],
        words: &["Force Control"],
        entries: force::ENTRIES,
    },
    SoftwareOption {
        short: "ProductionManager",
        name: "Production Manager",
        chapter: "options/production_manager",
        numbers: &["812"],
        words: &["Production Manager"],
        entries: production_manager::ENTRIES,
    },
];

/// The option a product description or a manifest's option name names, if it is one
/// the catalogue declares: `689-1 Externally Guided Motion (EGM)`, `EGM`, `633-1 Arc`,
/// `Arc`, `652-1 BullsEye` (compared without case).
pub fn find(description: &str) -> Option<&'static SoftwareOption> {
    let text = description.trim();
    let (number, rest) = split_number(text);
    ALL_OPTIONS.iter().find(|option| {
        number.is_some_and(|n| option.numbers.contains(&n))
            || rest.eq_ignore_ascii_case(option.short)
            || rest.eq_ignore_ascii_case(option.name)
            || option.words.iter().any(|word| contains_word(rest, word))
    })
}

/// The option whose entries are listed under catalogue chapter `chapter`.
pub fn of_chapter(chapter: &str) -> Option<&'static SoftwareOption> {
    ALL_OPTIONS.iter().find(|option| option.chapter == chapter)
}

/// `689-1 Externally…` → (`Some("689")`, `Externally…`); text without a number is
/// returned whole.
fn split_number(text: &str) -> (Option<&str>, &str) {
    let Some((head, rest)) = text.split_once(|c: char| c.is_whitespace()).or(Some((text, ""))) else {
        return (None, text);
    };
    match head.split_once('-') {
        Some((n, variant))
            if !n.is_empty()
                && n.bytes().all(|b| b.is_ascii_digit())
                && variant.bytes().all(|b| b.is_ascii_alphanumeric()) =>
        {
            (Some(n), rest.trim())
        }
        _ => (None, text),
    }
}

/// Whether `word` (possibly several words) occurs in `text` on word boundaries.
fn contains_word(text: &str, word: &str) -> bool {
    let (text, word) = (text.to_ascii_lowercase(), word.to_ascii_lowercase());
    text.match_indices(&word).any(|(at, _)| {
        let before = text[..at].chars().next_back().is_none_or(|c| !c.is_ascii_alphanumeric());
        let after = text[at + word.len()..].chars().next().is_none_or(|c| !c.is_ascii_alphanumeric());
        before && after
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn short(description: &str) -> Option<&'static str> {
        find(description).map(|o| o.short)
    }

    #[test]
    fn product_descriptions_name_their_options() {
        assert_eq!(short("689-1 Externally Guided Motion (EGM)"), Some("EGM"));
        assert_eq!(short("633-1 Arc"), Some("Arc"));
        assert_eq!(short("652-1 BullsEye"), Some("BullsEye"));
        assert_eq!(short("SmarTac"), Some("SmarTac"));
        assert_eq!(short("657-1 SmarTac IO version"), Some("SmarTac"));
        // Manifest spellings: the short name or the manual's name, any case.
        assert_eq!(short("egm"), Some("EGM"));
        assert_eq!(short("arc"), Some("Arc"));
        assert_eq!(short("Force Control"), Some("ForceControl"));
        assert_eq!(short("812-1 Production Manager"), Some("ProductionManager"));
        // Other products are no option of ours; "Arc" must be a whole word.
        assert_eq!(short("623-1 Multitasking"), None);
        assert_eq!(short("653-2 Binzel - TC97"), None);
        assert_eq!(short("Archive"), None);
        assert_eq!(short("RobotWare Base"), None);
    }
}
