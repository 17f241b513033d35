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
use rapid_controller::api::{ConfigDomain, ConfigInstance};

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
            let domains = domains.as_slice();
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
fn domain_list(domains: &[ConfigDomain]) -> Reply {
    let mut names: Vec<String> = domains.iter().map(|d| d.name.to_ascii_uppercase()).collect();
    names.sort_by_key(|d| (ORDER.iter().position(|o| o == d).unwrap_or(ORDER.len()), d.clone()));
    names.dedup();
    let items = names.into_iter().map(|d| Item::new("cfg-domain-li", &d).linked(format!("cfg/{d}"))).collect();
    Reply::Items { base: "/rw/".into(), items }
}

/// Domain `name` (any letter case).
fn find_domain<'a>(domains: &'a [ConfigDomain], name: &str) -> Result<&'a ConfigDomain, RwsError> {
    domains.iter().find(|d| d.name.eq_ignore_ascii_case(name)).ok_or_else(|| {
        if ORDER.iter().any(|d| d.eq_ignore_ascii_case(name)) {
            // A real controller always has the six domains, with ABB's defaults where
            // the system's files say nothing; those defaults are not public.
            RwsError::not_found(format!("domain {name}: the system was booted without {name}.cfg"))
        } else {
            RwsError::not_found(format!("no configuration domain `{name}`"))
        }
    })
}

/// `/rw/cfg/{domain}`: one page of its types.
fn types(domains: &[ConfigDomain], domain: &str, start: usize, limit: usize) -> Result<Reply, RwsError> {
    let found = find_domain(domains, domain)?;
    let items: Vec<Item> = found
        .types
        .iter()
        .skip(start)
        .take(limit)
        .map(|t| Item::new("cfg-dt-li", &t.name).linked(format!("{domain}/{}", t.name)))
        .collect();
    let next = (start.saturating_add(limit) < found.types.len())
        .then(|| format!("{domain}?start={}&limit={limit}", start + limit));
    Ok(Reply::Page { base: BASE.into(), items, next })
}

/// The type `ty` of `domain` (any letter case asked).
fn find_type<'a>(
    domains: &'a [ConfigDomain],
    domain: &str,
    ty: &str,
) -> Result<&'a rapid_controller::api::ConfigType, RwsError> {
    let found = find_domain(domains, domain)?;
    found
        .types
        .iter()
        .find(|t| t.name.eq_ignore_ascii_case(ty))
        .ok_or_else(|| RwsError::not_found(format!("domain {domain} has no type `{ty}`")))
}

/// `/rw/cfg/{domain}/{type}`: links to its instances (with their number) and attributes.
fn type_view(domains: &[ConfigDomain], domain: &str, ty: &str) -> Result<Reply, RwsError> {
    let found = find_type(domains, domain, ty)?;
    let name = &found.name;
    let items = vec![
        // The manual adds `cfg-no-of-attributes`, the schema's count: not public, so
        // not given rather than guessed from the attributes the file writes.
        Item::new("cfg-dt-attributes-li", "attributes").linked(format!("{domain}/{name}/attributes")),
        Item::new("cfg-dt-instances-li", "instances")
            .linked(format!("{domain}/{name}/instances"))
            .with("cfg-no-of-instances", found.instances.len().to_string()),
    ];
    Ok(Reply::Items { base: BASE.into(), items })
}

/// `/rw/cfg/{domain}/{type}/instances[/{name}]`: the instances with their attributes.
fn instances(domains: &[ConfigDomain], domain: &str, ty: &str, only: Option<&str>) -> Result<Reply, RwsError> {
    let found = find_type(domains, domain, ty)?;
    let items: Vec<Item> = found
        .instances
        .iter()
        .filter(|i| only.is_none_or(|n| i.name().is_some_and(|name| name.eq_ignore_ascii_case(n))))
        .map(instance_item)
        .collect();
    if let (Some(wanted), true) = (only, items.is_empty()) {
        return Err(RwsError::not_found(format!("type {} of domain {domain} has no instance `{wanted}`", found.name)));
    }
    Ok(Reply::Items { base: BASE.into(), items })
}

/// One instance as `cfg-dt-instance-li` titled by its name: not read-only (it came
/// from the system's files, not RobotWare's own), its id, and its attributes as the
/// file writes them.
// uncertain: RobotWare's instance ids are its own handles; ours (the instance's number
// in the domain's file) are stable while the system runs, which is what a client may
// rely on.
fn instance_item(instance: &ConfigInstance) -> Item {
    let attributes = instance
        .attributes
        .iter()
        .map(|(name, value)| {
            // uncertain: a flag attribute (written bare, `-Hidden`) shows as true.
            Item::new("cfg-ia-t-li", name).with("value", value.clone().unwrap_or_else(|| "true".to_owned()))
        })
        .collect();
    Item::new("cfg-dt-instance-li", instance.name().unwrap_or_default())
        .with("rdonly", "false")
        .with("instanceid", instance.number.to_string())
        .holding("attrib", attributes)
}
