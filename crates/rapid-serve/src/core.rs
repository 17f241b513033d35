//! The controller thread: it alone owns the [`Session`] and runs it under the clock
//! policy; HTTP handlers reach it through a bounded queue of jobs ([`Handle::call`])
//! and hear of changes through the subscription hub's broadcast channel, which never
//! blocks the controller (a subscriber that falls behind loses events and is told).
//!
//! A job is a closure run between two rounds of the controller; it gets the whole
//! [`Core`] (the session plus what RWS adds: the panel's operating mode, the run
//! mode, task activation, the event log's numbering) and its answer
//! goes back on a oneshot channel. The session is not `Send` (RAPID values share
//! their parts), so it is built on the thread itself from the boot closure.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{self, Receiver, RecvTimeoutError, SyncSender, TrySendError};
use std::sync::Arc;
use std::time::Duration;

use rapid_controller::api::{ClockPolicy, RunOutcome, Session, Subscription};
use tokio::sync::{broadcast, oneshot};

use crate::elog::Elog;
use crate::hub::Event;
use crate::model::RwsError;

/// Jobs waiting for the controller at most; more are refused as busy (503).
const QUEUE: usize = 256;
/// Statements one round runs before the queue is looked at again.
const ROUND: u64 = 2000;
/// How long the thread rests when nothing runs (a stopped program, ended tasks).
const IDLE: Duration = Duration::from_millis(10);
/// How long a handler waits for its answer.
const ANSWER_TIMEOUT: Duration = Duration::from_secs(10);
/// Events the hub buffers for a slow subscriber.
const EVENTS: usize = 4096;

type Job = Box<dyn FnOnce(&mut Core) + Send>;

/// Builds the session, on the controller thread.
pub type BuildSession = Box<dyn FnOnce() -> Result<Session, String> + Send>;
/// Runs when the server stops, on the controller thread (saving persistents).
pub type OnExit = Box<dyn FnOnce(&mut Session) -> Result<(), String> + Send>;
/// Gets each line the program writes on the pendant (TPWrite), on the controller
/// thread.
pub type OnTpWrite = Box<dyn FnMut(&str) + Send>;

/// What the controller thread is started with.
pub struct Boot {
    /// Builds the session on the controller thread.
    pub session: BuildSession,
    pub clock: ClockPolicy,
    /// Run on the controller thread when the server stops (saving persistents).
    pub on_exit: Option<OnExit>,
    /// Where the pendant's lines go besides the stream (a terminal).
    pub on_tp_write: Option<OnTpWrite>,
}

/// The controller and what RWS keeps beside it.
pub(crate) struct Core {
    pub(crate) session: Session,
    /// `/rw/panel/opmode`.
    pub(crate) opmode: &'static str,
    /// The run mode of the last start: `once`, `forever` (RobotWare's default).
    pub(crate) cycle: String,
    /// Module loads and unloads asked through RWS: a module text's `change-count`.
    pub(crate) module_changes: u64,
    /// Tasks deactivated through `/rw/rapid/tasks/{task}?action=deactivate`.
    pub(crate) inactive: Vec<String>,
    pub(crate) elog: Elog,
    /// The controller failed (an internal error, caught): it runs no more, and
    /// requests are still answered as far as they can be.
    failed: bool,
    /// Each task's program pointer last told, while the program stands stopped.
    told_pointers: Vec<Option<Event>>,
    /// The state last told subscribers: (ctrlexecstate, ctrlstate).
    told: (String, String),
    stream: Subscription,
    events: broadcast::Sender<Event>,
    on_tp_write: Option<OnTpWrite>,
}

impl Core {
    fn new(mut session: Session, events: broadcast::Sender<Event>, on_tp_write: Option<OnTpWrite>) -> Core {
        let stream = session.subscribe();
        let mut core = Core {
            session,
            opmode: "AUTO",
            cycle: "forever".to_owned(),
            module_changes: 0,
            inactive: Vec::new(),
            elog: Elog::default(),
            failed: false,
            told_pointers: Vec::new(),
            told: (String::new(), String::new()),
            stream,
            events,
            on_tp_write,
        };
        core.told = (core.exec_state().to_owned(), core.ctrl_state().to_owned());
        core.elog.boot(core.session.motors_on());
        core.session.set_cycles(0);
        core
    }

    /// `running` or `stopped`, as `/rw/rapid/execution` names it.
    pub(crate) fn exec_state(&self) -> &'static str {
        use rapid_controller::ProgramState as P;
        match self.session.program_state() {
            P::Running | P::Stopping { .. } | P::Stepping { .. } if !self.session.all_normal_ended() => "running",
            _ => "stopped",
        }
    }

    /// `motoron` or `motoroff`, as `/rw/panel/ctrlstate` names it.
    pub(crate) fn ctrl_state(&self) -> &'static str {
        if self.session.motors_on() {
            "motoron"
        } else {
            "motoroff"
        }
    }

    /// Tells subscribers of a panel change made through RWS.
    pub(crate) fn publish(&self, event: Event) {
        // No receiver is no error: nobody subscribed.
        let _ = self.events.send(event);
    }

    /// After every round and job: the stream's changes and the event log's new
    /// entries go to the hub, and so do changes of execution and controller state.
    pub(crate) fn after(&mut self) {
        let batch = match self.session.poll(self.stream) {
            Ok(batch) => batch,
            Err(_) => return,
        };
        for change in batch.changes {
            if let (rapid_controller::api::Change::TpWrite { text }, Some(out)) = (&change, &mut self.on_tp_write) {
                out(text);
            }
            if let Some(event) = Event::of_change(&change) {
                self.publish(event);
            }
        }
        for seq in self.elog.refresh(&self.session) {
            self.publish(Event::Elog { seq });
        }
        let now = (self.exec_state().to_owned(), self.ctrl_state().to_owned());
        if now.0 != self.told.0 {
            self.publish(Event::Execution { state: now.0.clone() });
        }
        if now.1 != self.told.1 {
            self.elog.motors(now.1 == "motoron");
            self.publish(Event::CtrlState { state: now.1.clone() });
        }
        if now.0 == "stopped" {
            self.tell_pointers();
        }
        self.told = now;
    }

    /// While the program stands stopped, each task's program pointer that moved (a
    /// stop, PP to Main, a step) is told once.
    fn tell_pointers(&mut self) {
        let tasks = self.session.tasks();
        self.told_pointers.resize(tasks.len(), None);
        for (idx, task) in tasks.iter().enumerate() {
            let Ok(Some(at)) = self.session.program_pointer(&task.name) else { continue };
            let module =
                std::path::Path::new(&at.file).file_stem().map_or_else(String::new, |s| s.to_string_lossy().into());
            let event = Event::ProgramPointer {
                task: task.name.clone(),
                routine: at.routine,
                module,
                position: format!("{},{}", at.line, at.column),
            };
            if self.told_pointers[idx].as_ref() != Some(&event) {
                self.publish(event.clone());
                self.told_pointers[idx] = Some(event);
            }
        }
    }
}

/// The handlers' side of the controller thread.
#[derive(Clone)]
pub(crate) struct Handle {
    jobs: SyncSender<Job>,
    events: broadcast::Sender<Event>,
}

impl Handle {
    /// Runs `f` on the controller thread and returns its answer. Busy (503) when the
    /// queue is full or the answer takes longer than [`ANSWER_TIMEOUT`].
    pub(crate) async fn call<R, F>(&self, f: F) -> Result<R, RwsError>
    where
        R: Send + 'static,
        F: FnOnce(&mut Core) -> R + Send + 'static,
    {
        let (tx, rx) = oneshot::channel();
        let job: Job = Box::new(move |core| {
            let answer = f(core);
            core.after();
            // The handler may have gone (its client hung up): nothing to do.
            let _ = tx.send(answer);
        });
        match self.jobs.try_send(job) {
            Ok(()) => {}
            Err(TrySendError::Full(_)) => return Err(RwsError::busy("the controller is busy: try again")),
            Err(TrySendError::Disconnected(_)) => return Err(RwsError::busy("the controller has stopped")),
        }
        match tokio::time::timeout(ANSWER_TIMEOUT, rx).await {
            Ok(Ok(answer)) => Ok(answer),
            Ok(Err(_)) => Err(RwsError::new(
                axum::http::StatusCode::INTERNAL_SERVER_ERROR,
                crate::model::CODE_BUSY,
                "the controller failed on this request (an internal error; please report it)",
            )),
            Err(_) => Err(RwsError::busy("the controller did not answer in time")),
        }
    }

    /// Tells subscribers of something that happened outside the controller (a DIPC
    /// message between clients).
    pub(crate) fn publish(&self, event: Event) {
        let _ = self.events.send(event);
    }

    /// A new listener to the controller's events.
    pub(crate) fn events(&self) -> broadcast::Receiver<Event> {
        self.events.subscribe()
    }
}

/// The running controller thread.
pub struct Controller {
    pub(crate) handle: Handle,
    /// The folder of the file devices (`<root>/HOME`, …), if the system has one.
    pub(crate) file_root: Option<std::path::PathBuf>,
    thread: std::thread::JoinHandle<Result<(), String>>,
    stop: Arc<AtomicBool>,
}

impl Controller {
    /// Boots the session on a thread of its own; Err when it does not boot.
    pub fn start(boot: Boot) -> Result<Controller, String> {
        let (jobs, rx) = mpsc::sync_channel::<Job>(QUEUE);
        let (events, _) = broadcast::channel(EVENTS);
        let (ready_tx, ready_rx) = mpsc::channel::<Result<Option<std::path::PathBuf>, String>>();
        let thread_events = events.clone();
        let stop = Arc::new(AtomicBool::new(false));
        let thread_stop = stop.clone();
        let thread = std::thread::Builder::new()
            .name("rapid-controller".into())
            .spawn(move || {
                let session = match (boot.session)() {
                    Ok(session) => session,
                    Err(message) => {
                        let _ = ready_tx.send(Err(message.clone()));
                        return Err(message);
                    }
                };
                let mut core = Core::new(session, thread_events, boot.on_tp_write);
                core.session.set_clock(boot.clock);
                // A served controller lives on after the cycle: its static tasks too.
                core.session.set_lives_on(true);
                let _ = ready_tx.send(Ok(core.session.file_root()));
                drive(&mut core, &rx, &thread_stop);
                match boot.on_exit {
                    Some(on_exit) => on_exit(&mut core.session),
                    None => Ok(()),
                }
            })
            .map_err(|e| format!("cannot start the controller thread: {e}"))?;
        let file_root = match ready_rx.recv() {
            Ok(Ok(root)) => root,
            Ok(Err(message)) => return Err(message),
            Err(_) => return Err("the controller thread ended while booting".into()),
        };
        Ok(Controller { handle: Handle { jobs, events }, file_root, thread, stop })
    }

    /// Stops the thread after the jobs queued so far and runs the exit closure (the
    /// persistents saved); its error, if any.
    pub fn shutdown(self) -> Result<(), String> {
        self.stop.store(true, Ordering::SeqCst);
        // Wake the thread if it rests; a full queue wakes it anyway.
        let _ = self.handle.jobs.try_send(Box::new(|_core: &mut Core| {}));
        self.thread.join().map_err(|_| "the controller thread panicked".to_owned())?
    }
}

/// The controller thread's loop: jobs, then a round of the program, then rest as long
/// as the clock asks (a paced clock's sleep, or [`IDLE`] when nothing runs), waking
/// for the next job.
fn drive(core: &mut Core, jobs: &Receiver<Job>, stop: &AtomicBool) {
    while !stop.load(Ordering::SeqCst) {
        for _ in 0..QUEUE {
            match jobs.try_recv() {
                Ok(job) => run_job(core, job),
                Err(mpsc::TryRecvError::Empty) => break,
                Err(mpsc::TryRecvError::Disconnected) => return,
            }
        }
        let outcome = match core.failed {
            true => RunOutcome::Stopped,
            false => guarded(|| core.session.run(ROUND)).unwrap_or_else(|| {
                core.failed = true;
                RunOutcome::Stopped
            }),
        };
        if guarded(|| core.after()).is_none() {
            core.failed = true;
        }
        let rest = match outcome {
            RunOutcome::Running => continue,
            RunOutcome::Sleep(d) => d.min(IDLE * 5),
            RunOutcome::Breakpoint(_) | RunOutcome::Stopped | RunOutcome::Ended => IDLE,
        };
        match jobs.recv_timeout(rest) {
            Ok(job) => run_job(core, job),
            Err(RecvTimeoutError::Timeout) => {}
            Err(RecvTimeoutError::Disconnected) => return,
        }
    }
}

/// Runs a job; a panic in it (an interpreter bug) is caught, its handler answered 500
/// (its answer channel dropped), and the controller marked failed.
fn run_job(core: &mut Core, job: Job) {
    if guarded(|| job(core)).is_none() {
        core.failed = true;
    }
}

/// `f()`, or None when it panics.
fn guarded<R>(f: impl FnOnce() -> R) -> Option<R> {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)).ok()
}
