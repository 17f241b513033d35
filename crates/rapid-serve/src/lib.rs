//! `rapid serve`'s library: Robot Web Services (RWS 1.0, as RobotWare 6 serves it) in
//! front of the virtual controller, so that unmodified ABB clients (abb-robot-client,
//! abb-motion-program-exec, abb_librws) talk to it as to a real IRC5.
//!
//! It knows HTTP and RWS, nothing of the command line. The controller runs on a
//! thread of its own (`core`), which alone owns the [`Session`]; HTTP handlers
//! (axum on tokio) send it jobs through a bounded queue and never hold it across an
//! await. Modules: `auth` (Digest and session cookies), `model` (items rendered as
//! XHTML or JSON, error bodies), `hub` (subscriptions and their websockets), `elog`
//! (the event log's numbering), `routes` (one module per resource family), `pendant`
//! (the web pendant at `/` and its JSON resources under `/pendant/api/`).
//!
//! A front end that wants more (a web pendant, a load test) reuses [`router`]'s
//! state: the controller handle for jobs and events, and the subscription hub.

mod auth;
mod core;
mod elog;
mod hub;
mod model;
mod pendant;
mod routes;

use std::net::SocketAddr;
use std::sync::Arc;

pub use crate::auth::{digest_authorization, Auth, DEFAULT_USER, REALM};
pub use crate::core::{Boot, BuildSession, Controller, OnExit, OnTpWrite};
pub use rapid_controller::api::{ClockPolicy, Session};

/// What the handlers share.
pub struct App {
    pub(crate) controller: core::Handle,
    pub(crate) auth: Auth,
    pub(crate) hub: Arc<hub::Hub>,
    pub(crate) dipc: routes::Dipc,
    pub(crate) file_root: Option<std::path::PathBuf>,
}

/// What a server is made of besides its controller.
pub struct Config {
    /// Users as (name, password): the default user, plus those of `--users`.
    pub users: Vec<(String, String)>,
}

impl Default for Config {
    fn default() -> Config {
        Config { users: vec![(DEFAULT_USER.0.to_owned(), DEFAULT_USER.1.to_owned())] }
    }
}

/// The router of a server in front of `controller` (for in-process tests, and to
/// serve on a listener of one's own).
pub fn router(controller: &Controller, config: Config) -> axum::Router {
    let app = App {
        controller: controller.handle.clone(),
        auth: Auth::new(config.users),
        hub: Arc::new(hub::Hub::default()),
        dipc: routes::Dipc::default(),
        file_root: controller.file_root.clone(),
    };
    routes::router(Arc::new(app))
}

/// Serves `router` on `listener` until `shutdown` completes; open connections are
/// then let go (websockets closed).
pub async fn serve(
    listener: tokio::net::TcpListener,
    router: axum::Router,
    shutdown: impl std::future::Future<Output = ()> + Send + 'static,
) -> std::io::Result<()> {
    let service = router.into_make_service_with_connect_info::<SocketAddr>();
    axum::serve(listener, service).with_graceful_shutdown(shutdown).await
}
