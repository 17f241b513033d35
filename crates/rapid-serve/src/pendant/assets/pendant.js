// The web pendant's script: RWS resources and the robapi2_subscription websocket as
// any RWS client uses them, plus the pendant's own JSON under /pendant/api/ for what
// RWS lacks (the pendant's screen and dialogs, the arms' geometry, module text).
// Plain browser JavaScript, no library, no build step.
"use strict";

const $ = (id) => document.getElementById(id);
let errors = 0;
window.addEventListener("error", () => { errors += 1; document.body.dataset.errors = String(errors); });

// ---- RWS over fetch -------------------------------------------------------------

/** Calls an RWS resource with json=1; the parsed answer, or null for an empty one. */
async function rws(method, path, form) {
  const url = path + (path.includes("?") ? "&" : "?") + "json=1";
  const init = { method, credentials: "same-origin", headers: {} };
  if (form) {
    init.body = new URLSearchParams(form).toString();
    init.headers["Content-Type"] = "application/x-www-form-urlencoded;v=2.0";
  }
  const res = await fetch(url, init);
  const text = await res.text();
  if (!res.ok) {
    let msg = res.status + " " + res.statusText;
    try { msg = JSON.parse(text)._embedded.status.msg; } catch (_) { /* not an RWS error body */ }
    throw new Error(msg);
  }
  return text ? JSON.parse(text) : null;
}

/** The items of an RWS JSON answer. */
const items = (doc) => (doc && doc._embedded && doc._embedded._state) || [];

/** Our own JSON resources. */
async function api(method, path, form) {
  const init = { method, credentials: "same-origin" };
  if (form) {
    init.body = new URLSearchParams(form).toString();
    init.headers = { "Content-Type": "application/x-www-form-urlencoded" };
  }
  const res = await fetch("/pendant/api/" + path, init);
  const text = await res.text();
  if (!res.ok) {
    let msg = res.status + "";
    try { msg = JSON.parse(text).error; } catch (_) { /* plain text */ }
    throw new Error(msg);
  }
  return text ? JSON.parse(text) : null;
}

/** Runs an operator's action; its error is shown in the header. */
async function act(what, f) {
  $("status").textContent = "";
  try { await f(); } catch (e) { $("status").textContent = what + ": " + e.message; }
}

const esc = (s) => String(s).replace(/[&<>"]/g, (c) => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;" })[c]);
const enc = (path) => path.split("/").map(encodeURIComponent).join("/");

// ---- execution and panel ---------------------------------------------------------

async function refreshExec() {
  const exec = items(await rws("GET", "/rw/rapid/execution"))[0] || {};
  showBadge("exec", exec.ctrlexecstate);
  const ctrl = items(await rws("GET", "/rw/panel/ctrlstate"))[0] || {};
  showBadge("motors", ctrl.ctrlstate);
}

function showBadge(id, text) {
  const el = $(id);
  el.textContent = text || "?";
  el.className = "badge " + (text || "");
}

const START = { regain: "continue", cycle: "asis", condition: "none", stopatbp: "disabled", alltaskbytsp: "false" };
$("start").onclick = () => act("start", () => rws("POST", "/rw/rapid/execution?action=start", { ...START, execmode: "continue" }));
$("step").onclick = () => act("step", () => rws("POST", "/rw/rapid/execution?action=start", { ...START, execmode: "stepover" }));
$("stop").onclick = () => act("stop", () => rws("POST", "/rw/rapid/execution?action=stop", { stopmode: "stop" }));
$("ppmain").onclick = () => act("PP to Main", () => rws("POST", "/rw/rapid/execution?action=resetpp"));

// ---- program view ----------------------------------------------------------------

const programs = {}; // task -> { file, text }

async function refreshTasks() {
  const tasks = items(await rws("GET", "/rw/rapid/tasks"));
  const select = $("task");
  select.innerHTML = tasks.map((t) => `<option>${esc(t.name)}</option>`).join("");
  select.onchange = () => refreshPointer();
  return tasks.map((t) => t.name);
}

async function refreshPointer() {
  const task = $("task").value;
  if (!task) return;
  const pcp = items(await rws("GET", `/rw/rapid/tasks/${encodeURIComponent(task)}/pcp`))[0] || {};
  const line = parseInt((pcp.beginposition || "").split(",")[0], 10);
  $("pointer").textContent = pcp.routinename ? `${pcp.modulemame} / ${pcp.routinename} line ${line}` : "no program pointer";
  let program = programs[task];
  const module = pcp.modulemame || "";
  if (!program || program.module !== module) {
    const p = await api("GET", "program?task=" + encodeURIComponent(task));
    program = programs[task] = { module, text: p.text };
  }
  showProgram(program.text, line);
}

function showProgram(text, line) {
  const pre = $("program");
  if (text == null) { pre.textContent = "(the module's text is not on disk)"; return; }
  pre.innerHTML = text.split(/\r?\n/).map((l, i) =>
    `<span class="${i + 1 === line ? "pp" : ""}" data-line="${i + 1}"><span class="ln">${i + 1}</span>${esc(l)}</span>`
  ).join("\n");
  const at = pre.querySelector(".pp");
  if (at) pre.scrollTop = Math.max(0, at.offsetTop - pre.offsetTop - pre.clientHeight / 3);
}

// ---- FlexPendant screen and dialogs ----------------------------------------------

let shownPrompts = null;

async function refreshScreen() {
  const screen = await api("GET", "screen");
  const tp = $("tp");
  const text = screen.lines.join("\n");
  if (tp.textContent !== text) { tp.textContent = text; tp.scrollTop = tp.scrollHeight; }
  const key = screen.prompts.map((p) => p.id).join(",");
  if (key === shownPrompts) return;
  shownPrompts = key;
  $("prompts").innerHTML = screen.prompts.map((p) => `
    <div class="prompt" data-prompt="${p.id}">
      <div><b>${esc(p.task)}</b>: ${esc(p.text)}</div>
      <input id="answer-${p.id}" placeholder="answer">
      <button data-answer="${p.id}">OK</button>
      ${[1, 2, 3, 4, 5].map((k) => `<button data-answer="${p.id}" data-key="${k}" title="function key ${k}">${k}</button>`).join("")}
    </div>`).join("");
  for (const b of $("prompts").querySelectorAll("button")) {
    b.onclick = () => {
      const id = b.dataset.answer;
      const answer = b.dataset.key || $("answer-" + id).value;
      act("answer", async () => { await api("POST", "answer", { id, answer }); shownPrompts = null; await refreshScreen(); });
    };
  }
}

// ---- I/O -------------------------------------------------------------------------

const signals = new Map(); // name -> { title, type, lvalue }

async function refreshSignals() {
  for (const s of items(await rws("GET", "/rw/iosystem/signals"))) {
    signals.set(s.name, { title: s._title, type: s.type, lvalue: s.lvalue });
  }
  showSignals();
}

function showSignals() {
  const rows = [...signals.entries()].map(([name, s]) => {
    const digital = s.type === "DI" || s.type === "DO";
    const on = digital && Number(s.lvalue) !== 0;
    const control = digital
      ? `<button class="toggle ${on ? "on" : ""}" data-signal="${esc(name)}">${on ? "1" : "0"}</button>`
      : `<span class="v">${esc(s.lvalue)}</span>`;
    return `<tr><td>${esc(name)}</td><td class="dim">${esc(s.type)}</td><td>${control}</td></tr>`;
  });
  $("signals").tBodies[0].innerHTML = rows.join("");
  for (const b of $("signals").querySelectorAll("button[data-signal]")) {
    b.onclick = () => act("set " + b.dataset.signal, () => {
      const s = signals.get(b.dataset.signal);
      const value = Number(s.lvalue) !== 0 ? "0" : "1";
      return rws("POST", `/rw/iosystem/signals/${enc(s.title)}?action=set`, { lvalue: value });
    });
  }
}

// ---- RAPID data watch --------------------------------------------------------------

let watched = []; // [{ url, name, type, kind }]
let editing = null;

async function findData(tasks) {
  watched = [];
  for (const task of tasks) {
    const found = items(await rws("POST", "/rw/rapid/symbols?action=search-symbols", { blockurl: "RAPID/" + task, symtyp: "any" }));
    for (const d of found) watched.push({ url: d.symburl, name: d.name, type: d.dattyp, kind: d.symtyp, task });
  }
  watched = watched.slice(0, 60);
}

async function refreshData() {
  if (editing) return;
  const rows = [];
  for (const d of watched) {
    let value;
    try { value = (items(await rws("GET", "/rw/rapid/symbol/data/" + enc(d.url)))[0] || {}).value; } catch (e) { value = "(" + e.message + ")"; }
    rows.push(`<tr><td title="${esc(d.url)}">${esc(d.name)}</td><td class="dim">${esc(d.kind)} ${esc(d.type)}</td>` +
      `<td class="v" data-url="${esc(d.url)}" title="${d.kind === "con" ? "a CONST" : "click to edit"}">${esc(value)}</td></tr>`);
  }
  if (editing) return;
  $("data").tBodies[0].innerHTML = rows.join("");
  for (const cell of $("data").querySelectorAll("td[data-url]")) cell.onclick = () => edit(cell);
}

function edit(cell) {
  if (editing) return;
  editing = cell.dataset.url;
  const input = document.createElement("input");
  input.value = cell.textContent;
  input.style.width = "100%";
  cell.textContent = "";
  cell.appendChild(input);
  input.focus();
  const done = async (save) => {
    if (save) await act("set " + editing, () => rws("POST", `/rw/rapid/symbol/data/${enc(editing)}?action=set`, { value: input.value }));
    editing = null;
    await refreshData();
  };
  input.onkeydown = (e) => { if (e.key === "Enter") done(true); if (e.key === "Escape") done(false); };
  input.onblur = () => { if (editing) done(false); };
}

// ---- event log -------------------------------------------------------------------

async function refreshElog() {
  const entries = items(await rws("GET", "/rw/elog/0?lang=en")).slice(0, 40);
  const kinds = { 1: "info", 2: "warning", 3: "error" };
  $("elog").tBodies[0].innerHTML = entries.map((e) =>
    `<tr><td class="dim">${esc(e.tstamp)}</td><td>${esc(kinds[e.msgtype] || e.msgtype)}</td><td>${esc(e.code)}</td><td>${esc(e.title)}</td></tr>`
  ).join("");
}

// ---- subscription ------------------------------------------------------------------

async function subscribe(tasks) {
  const resources = ["/rw/rapid/execution;ctrlexecstate", "/rw/panel/ctrlstate", "/rw/elog/0"];
  for (const t of tasks) resources.push(`/rw/rapid/tasks/${t}/pcp;programpointerchange`);
  for (const s of signals.values()) resources.push(`/rw/iosystem/signals/${s.title};state`);
  const form = new URLSearchParams();
  resources.forEach((r, i) => { form.append("resources", String(i + 1)); form.append(String(i + 1), r); form.append(`${i + 1}-p`, "1"); });
  const res = await fetch("/subscription", {
    method: "POST", credentials: "same-origin", body: form.toString(),
    headers: { "Content-Type": "application/x-www-form-urlencoded;v=2.0" },
  });
  if (res.status !== 201) throw new Error("subscription refused: " + res.status);
  const body = await res.text();
  const href = res.headers.get("Location") || (body.match(/href="(ws:[^"]+)" rel="self"/) || [])[1];
  const ws = new WebSocket(href.replace(/^ws:\/\/[^/]+/, "ws://" + location.host), "robapi2_subscription");
  ws.onmessage = (m) => onEvent(String(m.data));
  ws.onclose = () => setTimeout(() => subscribe(tasks).catch(() => {}), 2000);
}

function onEvent(text) {
  const doc = new DOMParser().parseFromString(text, "text/html");
  for (const li of doc.querySelectorAll("li")) {
    const span = (c) => (li.querySelector("span." + c) || {}).textContent;
    switch (li.className) {
      case "ios-signalstate-ev": {
        const name = li.getAttribute("title").split("/").pop();
        const s = signals.get(name);
        if (s) { s.lvalue = span("lvalue"); showSignals(); }
        break;
      }
      case "rap-ctrlexecstate-ev": showBadge("exec", span("ctrlexecstate")); refreshPointer().catch(() => {}); break;
      case "pnl-ctrlstate-ev": showBadge("motors", span("ctrlstate")); break;
      case "elog-message-ev": refreshElog().catch(() => {}); break;
      case "pcp-info": refreshPointer().catch(() => {}); break;
      default: break;
    }
  }
}

// ---- 3D view -----------------------------------------------------------------------

const view = { yaw: -0.6, pitch: 0.35, zoom: 1, arms: [], paths: [], extent: 500 };

async function refreshArms() {
  const answer = await api("GET", "arms");
  view.arms = answer.arms;
  answer.arms.forEach((a, i) => {
    const path = view.paths[i] || (view.paths[i] = []);
    const last = path[path.length - 1];
    if (!last || Math.hypot(a.tcp[0] - last[0], a.tcp[1] - last[1], a.tcp[2] - last[2]) > 0.5) path.push(a.tcp);
    if (path.length > 3000) path.shift();
  });
  // The scene is sized to the arms' reach (grown, never shrunk, so the view holds still).
  for (const arm of answer.arms) {
    for (const p of arm.points.concat([arm.tcp])) view.extent = Math.max(view.extent, Math.hypot(p[0], p[1]), p[2]);
  }
  const a = answer.arms[0];
  $("joints").textContent = a ? a.joints.map((j) => j.toFixed(1)).join("  ") : "no robot";
  draw();
}

function draw() {
  const canvas = $("view");
  // Draw at the size shown, so that lines stay sharp.
  if (canvas.clientWidth && canvas.width !== canvas.clientWidth) {
    canvas.width = canvas.clientWidth;
    canvas.height = Math.round(canvas.clientWidth * 0.75);
  }
  const g = canvas.getContext("2d");
  const w = canvas.width, h = canvas.height;
  g.clearRect(0, 0, w, h);
  const grid = Math.ceil(view.extent / 250) * 250;
  const scale = (Math.min(w, h) / (2.4 * grid)) * view.zoom;
  const cy = Math.cos(view.yaw), sy = Math.sin(view.yaw), cp = Math.cos(view.pitch), sp = Math.sin(view.pitch);
  // World (x, y, z up, mm) to the canvas: turned about z by yaw, tilted by pitch.
  const P = ([x, y, z]) => {
    const x1 = x * cy - y * sy, y1 = x * sy + y * cy;
    return [w / 2 + x1 * scale, h * 0.62 - (z * cp + y1 * sp) * scale];
  };
  const line = (pts, color, width) => {
    g.strokeStyle = color; g.lineWidth = width; g.lineCap = "round"; g.lineJoin = "round";
    g.beginPath();
    pts.forEach((p, i) => { const [u, v] = P(p); if (i) g.lineTo(u, v); else g.moveTo(u, v); });
    g.stroke();
  };
  for (let k = -grid; k <= grid; k += grid / 4) {
    line([[k, -grid, 0], [k, grid, 0]], "#dde2e7", 1);
    line([[-grid, k, 0], [grid, k, 0]], "#dde2e7", 1);
  }
  line([[0, 0, 0], [grid / 4, 0, 0]], "#d33", 2);
  line([[0, 0, 0], [0, grid / 4, 0]], "#3a3", 2);
  line([[0, 0, 0], [0, 0, grid / 4]], "#33d", 2);
  view.paths.forEach((path) => { if (path.length > 1) line(path, "#1e74d0", 2); });
  for (const a of view.arms) {
    line(a.points.slice(0, 2), "#59636d", 22);
    line(a.points.slice(1), "#f29111", 12);
    line([a.points[a.points.length - 1], a.tcp], "#59636d", 4);
    for (const p of a.points) { const [u, v] = P(p); g.fillStyle = "#333"; g.beginPath(); g.arc(u, v, 3.5, 0, 7); g.fill(); }
    const [u, v] = P(a.tcp);
    g.fillStyle = "#d22"; g.beginPath(); g.arc(u, v, 4, 0, 7); g.fill();
  }
}

function viewControls() {
  const canvas = $("view");
  let drag = null;
  canvas.onmousedown = (e) => { drag = [e.clientX, e.clientY]; };
  window.addEventListener("mouseup", () => { drag = null; });
  canvas.onmousemove = (e) => {
    if (!drag) return;
    view.yaw += (e.clientX - drag[0]) * 0.01;
    view.pitch = Math.max(-1.5, Math.min(1.5, view.pitch + (e.clientY - drag[1]) * 0.01));
    drag = [e.clientX, e.clientY];
    draw();
  };
  canvas.onwheel = (e) => { e.preventDefault(); view.zoom *= e.deltaY < 0 ? 1.1 : 1 / 1.1; draw(); };
}

// ---- start ---------------------------------------------------------------------------

/** Runs `f` every `ms`, one call at a time (a slow answer delays the next). */
function every(ms, f) {
  const tick = async () => { try { await f(); } catch (_) { /* shown on the next success */ } setTimeout(tick, ms); };
  tick();
}

async function main() {
  viewControls();
  const tasks = await refreshTasks();
  await Promise.all([refreshExec(), refreshSignals(), refreshElog(), refreshPointer()]);
  await findData(tasks);
  await refreshData();
  await subscribe(tasks).catch((e) => { $("status").textContent = e.message; });
  every(250, refreshScreen);
  every(100, refreshArms);
  every(2000, refreshData);
  every(3000, refreshExec);
  // RWS tells the program pointer only while the program stands; while it runs, look.
  every(500, refreshPointer);
  document.body.dataset.ready = "yes";
}

main().catch((e) => { $("status").textContent = "the pendant did not start: " + e.message; });
