//! The system parameters a task's ReadCfgData, WriteCfgData, SaveCfgData and
//! GetModalPayLoadMode work on: the configuration files (a backup's `SYSPAR/*.cfg`) as
//! `rapid-config` parses them, one per domain, behind the VM's
//! `crate::bindings::cfgdata::CfgDatabase`. An edit rewrites the file's text and
//! parses it again, so that SaveCfgData writes every other byte as it was read.

use std::any::Any;

use crate::bindings::cfgdata::{CfgAttr, CfgDatabase, CfgEdit, CfgState, InstanceAt, Unwritable};
use rapid_config::{Attr, CfgFile, Instance};

/// The configuration of a task: (domain such as `EIO`, parsed file) pairs; an
/// instance is at (section index, instance index) of its domain's file.
#[derive(Debug, Clone, Default)]
pub struct SysParams {
    domains: Vec<(String, CfgFile)>,
}

impl SysParams {
    /// The configuration of (domain, parsed file) pairs.
    pub fn new(domains: Vec<(String, CfgFile)>) -> SysParams {
        SysParams { domains }
    }

    /// The configuration as it stands: (domain, parsed file) pairs, WriteCfgData's
    /// changes included.
    pub fn domains(&self) -> &[(String, CfgFile)] {
        &self.domains
    }

    /// The domains of the configuration a task holds; none when it was given none.
    pub fn of(state: &CfgState) -> &[(String, CfgFile)] {
        let params = state.database().and_then(|db| db.as_any().downcast_ref::<SysParams>());
        params.map_or(&[], SysParams::domains)
    }

    fn instance(&self, domain: usize, at: InstanceAt) -> Option<&Instance> {
        let file = &self.domains.get(domain)?.1;
        file.sections.get(at.0)?.instances.get(at.1)
    }
}

/// An attribute as the VM sees it: a flag, a quoted value or a bare one.
fn cfg_attr(attr: &Attr) -> CfgAttr {
    match &attr.value {
        None => CfgAttr::Flag,
        Some(v) if v.quoted => CfgAttr::Quoted(v.text.clone()),
        Some(v) => CfgAttr::Bare(v.text.clone()),
    }
}

impl CfgDatabase for SysParams {
    fn as_any(&self) -> &dyn Any {
        self
    }

    fn domain_count(&self) -> usize {
        self.domains.len()
    }

    fn domain_name(&self, domain: usize) -> &str {
        self.domains.get(domain).map_or("", |(name, _)| name.as_str())
    }

    fn domain_text(&self, domain: usize) -> &str {
        self.domains.get(domain).map_or("", |(_, file)| file.text.as_str())
    }

    fn find(&self, domain: usize, type_name: &str, attr: &str, value: &str) -> Vec<InstanceAt> {
        let Some((_, file)) = self.domains.get(domain) else { return Vec::new() };
        let mut found = Vec::new();
        for (si, section) in file.sections.iter().enumerate() {
            if !section.name.eq_ignore_ascii_case(type_name) {
                continue;
            }
            for (ii, inst) in section.instances.iter().enumerate() {
                // uncertain: values compare without regard to case (names on the controller
                // ignore case); an attribute other than Name compares as written otherwise.
                if inst.value(attr).is_some_and(|v| v.eq_ignore_ascii_case(value)) {
                    found.push((si, ii));
                }
            }
        }
        found
    }

    fn attr(&self, domain: usize, at: InstanceAt, name: &str) -> Option<CfgAttr> {
        self.instance(domain, at)?.attr(name).map(cfg_attr)
    }

    fn attr_of_type(&self, domain: usize, at: InstanceAt, name: &str) -> Option<CfgAttr> {
        let file = &self.domains.get(domain)?.1;
        let type_name = &file.sections.get(at.0)?.name;
        file.instances(type_name).find_map(|i| i.attr(name)).map(cfg_attr)
    }

    fn edit(&mut self, domain: usize, at: InstanceAt, name: &str, edit: CfgEdit<'_>) -> Result<(), Unwritable> {
        let Some((_, file)) = self.domains.get_mut(domain) else { return Ok(()) };
        let (section, inst) = at;
        let edited = match edit {
            CfgEdit::SetFlag => file.with_flag(section, inst, name).ok().flatten(),
            CfgEdit::Remove => file.without_attr(section, inst, name).ok().flatten(),
            CfgEdit::Value(value) => Some(file.with_value(section, inst, name, value).map_err(|_| Unwritable)?),
        };
        if let Some(text) = edited {
            *file = rapid_config::parse(&text);
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn with_sys(text: &str) -> CfgState {
        let mut state = CfgState::default();
        state.set_config(Box::new(SysParams::new(vec![("SYS".to_owned(), rapid_config::parse(text))])));
        state
    }

    #[test]
    fn modal_pay_load_mode_reads_general_rapid() {
        let off = "SYS:CFG_1.0:6:0::\n#\nGENERAL_RAPID:\n\n      -Name \"SimulateMenu\" -Value 1\n\n      -Name \"ModalPayLoadMode\" -Value 0\n";
        assert_eq!(with_sys(off).modal_pay_load_mode(), 0.0);
        let on = "SYS:CFG_1.0:6:0::\n#\nGENERAL_RAPID:\n\n      -name \"modalpayloadmode\" -value 1\n";
        assert_eq!(with_sys(on).modal_pay_load_mode(), 1.0);
    }

    #[test]
    fn modal_pay_load_mode_defaults_to_modal() {
        // No configuration at all, a SYS.cfg without the parameter, another domain only.
        assert_eq!(CfgState::default().modal_pay_load_mode(), 1.0);
        let other = "SYS:CFG_1.0:6:0::\n#\nGENERAL_RAPID:\n\n      -Name \"SimulateMenu\" -Value 0\n";
        assert_eq!(with_sys(other).modal_pay_load_mode(), 1.0);
        let mut eio_only = CfgState::default();
        let eio = vec![("EIO".to_owned(), rapid_config::parse("EIO:CFG_1.0:6:0::\n"))];
        eio_only.set_config(Box::new(SysParams::new(eio)));
        assert_eq!(eio_only.modal_pay_load_mode(), 1.0);
    }

    #[test]
    fn edits_keep_every_other_byte_and_refuse_a_quote() {
        let text = "EIO:CFG_1.0:6:0::\n#\nEIO_SIGNAL:\n\n      -Name \"di1\" -SignalType \"DI\"\n";
        let mut params = SysParams::new(vec![("EIO".to_owned(), rapid_config::parse(text))]);
        let at = params.find(0, "eio_signal", "NAME", "DI1");
        assert_eq!(at, vec![(0, 0)]);
        assert_eq!(params.edit(0, at[0], "Access", CfgEdit::Value("All")), Ok(()));
        assert_eq!(params.attr(0, at[0], "Access"), Some(CfgAttr::Quoted("All".to_owned())));
        assert_eq!(params.edit(0, at[0], "Access", CfgEdit::Value("a\"b")), Err(Unwritable));
        assert_eq!(params.edit(0, at[0], "Access", CfgEdit::Remove), Ok(()));
        assert_eq!(params.domain_text(0), text);
    }
}
