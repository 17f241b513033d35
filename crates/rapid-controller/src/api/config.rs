//! The system parameters for front ends (RWS's `/rw/cfg`): the configuration domains
//! the controller booted with (a backup's or a layout's `EIO.cfg`, `SYS.cfg`,
//! `MOC.cfg`, …), as domains of types of instances, each instance's attributes as
//! its file writes them.

use super::Session;
use crate::boot::cfgdata::SysParams;

/// A configuration domain (`EIO`, `SYS`, …).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ConfigDomain {
    pub name: String,
    /// Its types in file order, each once (sections of one type joined).
    pub types: Vec<ConfigType>,
}

/// A type of a domain (`EIO_SIGNAL`) and its instances.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ConfigType {
    /// As the file writes it.
    pub name: String,
    pub instances: Vec<ConfigInstance>,
}

/// One instance.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ConfigInstance {
    /// Its number in the domain's file, from 1 (stable while the system runs).
    pub number: usize,
    /// (attribute as written, value without quotes; `None` for a bare flag).
    pub attributes: Vec<(String, Option<String>)>,
}

impl ConfigInstance {
    /// The value of its `-Name` attribute, if it has one.
    pub fn name(&self) -> Option<&str> {
        self.attributes.iter().find(|(a, _)| a.eq_ignore_ascii_case("Name")).and_then(|(_, v)| v.as_deref())
    }
}

impl Session {
    /// The configuration domains in the order the system gave them; none when the
    /// program was booted without configuration. They are the first task's, which its
    /// WriteCfgData changes (each task reads and writes a copy of its own, as
    /// `boot::cfgdata::SysParams` keeps them).
    pub fn configuration(&self) -> Vec<ConfigDomain> {
        let Some(task) = self.controller.tasks.first() else { return Vec::new() };
        SysParams::of(crate::bindings::cfgdata::of(task.loaded.vm.resources()))
            .iter()
            .map(|(name, file)| domain(name, file))
            .collect()
    }
}

/// A parsed file as a domain.
fn domain(name: &str, file: &rapid_config::CfgFile) -> ConfigDomain {
    let mut types: Vec<ConfigType> = Vec::new();
    let mut number = 0;
    for section in &file.sections {
        let at = match types.iter().position(|t| t.name.eq_ignore_ascii_case(&section.name)) {
            Some(at) => at,
            None => {
                types.push(ConfigType { name: section.name.clone(), instances: Vec::new() });
                types.len() - 1
            }
        };
        for instance in &section.instances {
            number += 1;
            let attributes =
                instance.attrs.iter().map(|a| (a.name.clone(), a.value.as_ref().map(|v| v.text.clone()))).collect();
            types[at].instances.push(ConfigInstance { number, attributes });
        }
    }
    ConfigDomain { name: name.to_owned(), types }
}
