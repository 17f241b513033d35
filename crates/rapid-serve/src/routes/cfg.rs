//! `/rw/cfg`: the configuration database (system parameters) as RobotWare 6 serves it,
//! read from the domains the controller booted with (`Session::configuration`).
//!
//! - `/rw/cfg`: the domains, `cfg-domain-li` each, linked `cfg/{DOMAIN}`;
//! - `/rw/cfg/{domain}`: its types, `cfg-dt-li` linked `{domain}/{TYPE}`, paged by
//!   `start` (the first one's index) and `limit` (at most and by default 70, with a
//!   `next` link while more follow);
//! - `/rw/cfg/{domain}/{type}`: `cfg-dt-instances-li` (linked, `cfg-no-of-instances`)
//!   and `cfg-dt-attributes-li` (linked);
//! - `/rw/cfg/{domain}/{type}/instances[/{name}]`: `cfg-dt-instance-li` titled by the
//!   instance's name, with `rdonly` and `instanceid`, holding one `cfg-ia-t-li` per
//!   attribute (titled by its name, span `value`); in JSON those are the item's
//!   `attrib` list.
//!
//! The class names, spans and paging are the RWS manual's (3HAC050973-001); the JSON
//! key `attrib` is what public clients of RW6 read (uncertain: the manual shows XHTML
//! only). Changing the configuration (`action=set`, create, delete, reset, load,
//! save) is refused as not supported: a faithful write needs ABB's parameter schema
//! (types, limits, which changes need a restart), which is not public.

use std::sync::Arc;

use axum::http::Method;
use rapid_config::{CfgFile, Instance};

use super::{not_found, Req, Res};
use crate::model::{Item, Reply, RwsError};
use crate::App;

/// The base of every answer below the domain list.
const BASE: &str = "/rw/cfg/";
/// Types a page holds at most (and by default), as the RWS manual says.
const PAGE: usize = 70;
/// The domains in the order RobotWare lists them.
const ORDER: [&str; 6] = ["EIO", "MMC", "MOC", "PROC", "SIO", "SYS"];

pub(super) async fn route(app: &Arc<App>, req: &Req) -> Res {
    let rest: Vec<String> = req.segs[2..].to_vec();
    if !req.is(Method::GET) {
        return Err(RwsError::unsupported(
            "changing the configuration through RWS (set, create, delete, reset, load, save): \
             without ABB's parameter schema a change cannot be checked as the controller checks it",
        ));
    }
    if req.action().is_some_and(|a| a != "show") {
        return Err(not_found(req));
    }
    if req.action() == Some("show") {
        return Err(RwsError::unsupported("the configuration's action forms (action=show)"));
    }
    let start = number(req.query("start"), 0, "start")?;
    let limit = number(req.query("limit"), PAGE, "limit")?.clamp(1, PAGE);
    let reply = app
        .controller
        .call(move |core| {
            let domains = core.session.configuration();
            match rest.as_slice() {
                [] => Ok(domain_list(domains)),
                [domain] => types(domains, domain, start, limit),
                [domain, ty] => type_view(domains, domain, ty),
                [domain, ty, part] if part == "attributes" => {
                    find_type(domains, domain, ty)?;
                    Err(RwsError::unsupported(
                        "a type's attributes with their kinds and limits: ABB's parameter schema is not public",
                    ))
                }
                [domain, ty, part] if part == "instances" => instances(domains, domain, ty, None),
                [domain, ty, part, name] if part == "instances" => instances(domains, domain, ty, Some(name)),
                _ => Err(RwsError::not_found(format!("no resource /rw/cfg/{}", rest.join("/")))),
            }
        })
        .await??;
    Ok(reply)
}

/// A paging parameter: absent is `default`, else a whole number.
fn number(text: Option<&str>, default: usize, name: &str) -> Result<usize, RwsError> {
    match text {
        None => Ok(default),
        Some(t) => t.trim().parse().map_err(|_| RwsError::bad_request(format!("{name} `{t}`: a whole number"))),
    }
}

/// `/rw/cfg`: the domains the system has, in RobotWare's order (others after).
fn domain_list(domains: &[(String, CfgFile)]) -> Reply {
    let mut names: Vec<String> = domains.iter().map(|(d, _)| d.to_ascii_uppercase()).collect();
    names.sort_by_key(|d| (ORDER.iter().position(|o| o == d).unwrap_or(ORDER.len()), d.clone()));
    names.dedup();
    let items = names.into_iter().map(|d| Item::new("cfg-domain-li", &d).linked(format!("cfg/{d}"))).collect();
    Reply::Items { base: "/rw/".into(), items }
}

/// The file of domain `name` (any letter case).
fn find_domain<'a>(domains: &'a [(String, CfgFile)], name: &str) -> Result<&'a CfgFile, RwsError> {
    domains.iter().find(|(d, _)| d.eq_ignore_ascii_case(name)).map(|(_, f)| f).ok_or_else(|| {
        if ORDER.iter().any(|d| d.eq_ignore_ascii_case(name)) {
            // A real controller always has the six domains, with ABB's defaults where
            // the system's files say nothing; those defaults are not public.
            RwsError::not_found(format!("domain {name}: the system was booted without {name}.cfg"))
        } else {
            RwsError::not_found(format!("no configuration domain `{name}`"))
        }
    })
}

/// The types of a domain, each once, in file order.
fn type_names(file: &CfgFile) -> Vec<&str> {
    let mut names: Vec<&str> = Vec::new();
    for section in &file.sections {
        if !names.iter().any(|n| n.eq_ignore_ascii_case(&section.name)) {
            names.push(&section.name);
        }
    }
    names
}

/// `/rw/cfg/{domain}`: one page of its types.
fn types(domains: &[(String, CfgFile)], domain: &str, start: usize, limit: usize) -> Result<Reply, RwsError> {
    let names = type_names(find_domain(domains, domain)?);
    let items: Vec<Item> = names
        .iter()
        .skip(start)
        .take(limit)
        .map(|t| Item::new("cfg-dt-li", t).linked(format!("{domain}/{t}")))
        .collect();
    let next =
        (start.saturating_add(limit) < names.len()).then(|| format!("{domain}?start={}&limit={limit}", start + limit));
    Ok(Reply::Page { base: BASE.into(), items, next })
}

/// The type `ty` of `domain` as written in the file (any letter case asked).
fn find_type<'a>(domains: &'a [(String, CfgFile)], domain: &str, ty: &str) -> Result<(&'a CfgFile, String), RwsError> {
    let file = find_domain(domains, domain)?;
    let name = type_names(file).into_iter().find(|t| t.eq_ignore_ascii_case(ty));
    let name = name.ok_or_else(|| RwsError::not_found(format!("domain {domain} has no type `{ty}`")))?;
    Ok((file, name.to_owned()))
}

/// `/rw/cfg/{domain}/{type}`: links to its instances (with their number) and attributes.
fn type_view(domains: &[(String, CfgFile)], domain: &str, ty: &str) -> Result<Reply, RwsError> {
    let (file, name) = find_type(domains, domain, ty)?;
    let count = file.instances(&name).count();
    let items = vec![
        // The manual adds `cfg-no-of-attributes`, the schema's count: not public, so
        // not given rather than guessed from the attributes the file writes.
        Item::new("cfg-dt-attributes-li", "attributes").linked(format!("{domain}/{name}/attributes")),
        Item::new("cfg-dt-instances-li", "instances")
            .linked(format!("{domain}/{name}/instances"))
            .with("cfg-no-of-instances", count.to_string()),
    ];
    Ok(Reply::Items { base: BASE.into(), items })
}

/// `/rw/cfg/{domain}/{type}/instances[/{name}]`: the instances with their attributes.
fn instances(domains: &[(String, CfgFile)], domain: &str, ty: &str, only: Option<&str>) -> Result<Reply, RwsError> {
    let (file, name) = find_type(domains, domain, ty)?;
    let mut items = Vec::new();
    for (id, section, instance) in numbered(file) {
        let title = instance.value("Name").unwrap_or_default();
        if section != name || only.is_some_and(|n| !n.eq_ignore_ascii_case(title)) {
            continue;
        }
        items.push(instance_item(title, id, instance));
    }
    if let (Some(wanted), true) = (only, items.is_empty()) {
        return Err(RwsError::not_found(format!("type {name} of domain {domain} has no instance `{wanted}`")));
    }
    Ok(Reply::Items { base: BASE.into(), items })
}

/// Every instance of the domain with its `instanceid`: its number in the file, from 1.
// uncertain: RobotWare's instance ids are its own handles; ours are stable for one
// boot, which is what a client may rely on.
fn numbered(file: &CfgFile) -> impl Iterator<Item = (usize, &str, &Instance)> {
    let all = file.sections.iter().flat_map(|s| s.instances.iter().map(move |i| (s.name.as_str(), i)));
    all.enumerate().map(|(n, (section, inst))| (n + 1, section, inst))
}

/// One instance as `cfg-dt-instance-li`: not read-only (it came from the system's
/// files, not RobotWare's own), its id, and its attributes as the file writes them.
fn instance_item(title: &str, id: usize, instance: &Instance) -> Item {
    let attributes = instance
        .attrs
        .iter()
        .map(|a| {
            // uncertain: a flag attribute (written bare, `-Hidden`) shows as true.
            let value = a.value.as_ref().map_or_else(|| "true".to_owned(), |v| v.text.clone());
            Item::new("cfg-ia-t-li", &a.name).with("value", value)
        })
        .collect();
    Item::new("cfg-dt-instance-li", title)
        .with("rdonly", "false")
        .with("instanceid", id.to_string())
        .holding("attrib", attributes)
}
