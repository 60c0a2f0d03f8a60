// The viewer: pick or paste a dungeon, draw it, solve it, step through the plan, or play.
// Every computation happens on the server (POST /replay runs actions and returns frames);
// this file only keeps the page's state and draws it (draw.js).
import { AGENT_COLOR, blockColor, draw, topBlocks } from "./draw.js";

const $ = (id) => document.getElementById(id);
// Letter keys come with each scene (`scene.keys`, the same table as `bcc play`); the
// arrow keys are this page's aliases for moving, turning and looking.
const ARROWS = {
  ArrowUp: "move_forward", ArrowLeft: "rotate_left", ArrowRight: "rotate_right",
  ArrowDown: "look_down", PageUp: "look_ahead",
};

function actionForKey(key) {
  const keys = (view.scene && view.scene.keys) || {};
  return keys[key] || keys[key.toLowerCase?.()] || ARROWS[key];
}

function keyOf(action) {
  const keys = (view.scene && view.scene.keys) || {};
  return Object.keys(keys).find((k) => keys[k] === action);
}

const view = {
  shipped: {},          // name -> YAML text of shipped dungeons
  scene: null,          // static drawing data of the current dungeon
  frames: [],           // one per state of the plan or the game
  actions: [],          // the actions between frames
  step: 0,
  result: null,         // the last solve result
  playing: false,       // play mode on
  timer: null,          // animation
  job: null,            // running job id
};
window.bccView = view;  // for the browser tests and the curious

async function api(method, path, body) {
  const response = await fetch(path, {
    method,
    headers: body ? { "content-type": "application/json" } : {},
    body: body ? JSON.stringify(body) : undefined,
  });
  let data = null;
  try { data = await response.json(); } catch { data = { error: `HTTP ${response.status}` }; }
  if (!response.ok) {
    const err = new Error(typeof data.error === "string" ? data.error : JSON.stringify(data.detail || data));
    err.body = data;
    throw err;
  }
  return data;
}

// kind: "ok" (default), "bad" (a failure: drawn in the error colour) or "busy".
function setStatus(text, kind = "ok") {
  $("status").textContent = text;
  $("status").dataset.kind = kind;
}

function showError(err) {
  const box = $("error");
  if (!err) { box.hidden = true; box.textContent = ""; return; }
  const b = err.body || {};
  let where = "";
  if (b.line) where = `line ${b.line}, column ${b.column}` + (b.file && b.file !== "<posted>" ? ` of ${b.file}` : "") + ": ";
  box.textContent = where + err.message;
  box.hidden = false;
  if (b.line && b.file === "<posted>") selectLine($("yaml"), b.line);
}

function selectLine(textarea, line) {
  const lines = textarea.value.split("\n");
  const start = lines.slice(0, line - 1).reduce((n, l) => n + l.length + 1, 0);
  textarea.focus();
  textarea.setSelectionRange(start, start + (lines[line - 1] || "").length);
  textarea.blur();
}

// What the `dungeon` field of a request is: the shipped name while its text is unchanged.
function dungeonField() {
  const name = $("dungeon-select").value;
  const text = $("yaml").value;
  return name && view.shipped[name] === text ? name : text;
}

function request(extra = {}) {
  const goal = $("goal").value.trim();
  return { dungeon: dungeonField(), goal: goal || null, ...extra };
}

// ---- drawing and stepping ------------------------------------------------------
function render() {
  if (!view.scene || !view.frames.length) return;
  const frame = view.frames[view.step];
  const path = view.frames.slice(0, view.step + 1).map((f) => f.agent);
  draw($("canvas"), view.scene, frame, path);
  $("canvas").dataset.step = String(view.step);
  $("canvas").dataset.agent = frame.agent.join(",");
  $("scrub").max = String(view.frames.length - 1);
  $("scrub").value = String(view.step);
  $("step-label").textContent = `step ${view.step} / ${view.frames.length - 1}` +
    (frame.goal ? " · goal reached" : "") + (frame.failure ? " · failed" : "");
  [...$("plan").children].forEach((li, i) => li.classList.toggle("current", i === view.step - 1));
  const rows = [["position", frame.agent.join(", ")], ["facing", frame.facing ?? "—"]];
  for (const [k, v] of Object.entries(frame.variables)) {
    if (/count$/.test(k) && v === 0) continue;
    if (/blockType$/.test(k) && v === "air") continue;
    rows.push([k, String(v)]);
  }
  table($("state"), rows);
}

function showLegend() {
  const item = (color, text, raised) => {
    const span = document.createElement("span");
    const swatch = document.createElement("i");
    swatch.style.background = color;
    if (raised) swatch.className = "raised";
    span.append(swatch, text);
    return span;
  };
  const names = topBlocks(view.scene);
  $("legend").replaceChildren(
    ...names.map((n) => item(blockColor(n, false), n)),
    item(blockColor("bedrock", true), "raised: wall / obstacle at the agent's level", true),
    item(AGENT_COLOR, "agent (arrow: facing; ring: looking down)"));
}

function table(el, rows) {
  el.replaceChildren(...rows.map(([k, v]) => {
    const tr = document.createElement("tr");
    const th = document.createElement("th"); th.textContent = k;
    const td = document.createElement("td"); td.textContent = v;
    tr.append(th, td);
    return tr;
  }));
}

function showPlan(actions) {
  $("plan").replaceChildren(...actions.map((a, i) => {
    const li = document.createElement("li");
    li.textContent = a;
    li.addEventListener("click", () => { stopAnimation(); view.step = i + 1; render(); });
    return li;
  }));
}

function goTo(step) {
  view.step = Math.max(0, Math.min(view.frames.length - 1, step));
  render();
}

function stopAnimation() {
  if (view.timer) clearInterval(view.timer);
  view.timer = null;
  $("play-btn").textContent = "Play";
}

function animate() {
  if (view.timer) { stopAnimation(); return; }
  if (view.step >= view.frames.length - 1) view.step = 0;
  $("play-btn").textContent = "Pause";
  view.timer = setInterval(() => {
    if (view.step >= view.frames.length - 1) { stopAnimation(); return; }
    goTo(view.step + 1);
  }, 350);
}

async function replay(actions) {
  const data = await api("POST", "/replay", request({ actions }));
  view.scene = data.scene;
  view.frames = data.frames;
  view.actions = actions.slice(0, data.steps);
  return data;
}

async function drawDungeon() {
  stopAnimation();
  showError(null);
  setStatus("compiling…", "busy");
  try {
    await replay([]);
    view.step = 0;
    view.result = null;
    showPlan([]);
    table($("stats"), [["dungeon", view.scene.dungeon], ["goal", view.scene.goal],
      ["size", `${view.scene.width} × ${view.scene.depth} × ${view.scene.height}`]]);
    render();
    showLegend();
    syncDungeonSelect();
    setStatus(`${view.scene.dungeon}: drawn`);
    setupActionButtons();
  } catch (err) {
    showError(err);
    setStatus("error", "bad");
  }
}

// The dropdown names what is drawn: a shipped dungeon whose text is unchanged, or
// "your dungeon" for pasted, uploaded or edited text.
function syncDungeonSelect() {
  const select = $("dungeon-select");
  const text = $("yaml").value;
  const shipped = Object.keys(view.shipped).find((n) => view.shipped[n] === text);
  let own = select.querySelector("option[data-own]");
  if (shipped) {
    if (own) own.remove();
    select.value = shipped;
    return;
  }
  if (!own) {
    own = new Option(`your dungeon — ${view.scene.dungeon}`, "");
    own.dataset.own = "1";
    select.prepend(own);
  }
  own.textContent = `your dungeon — ${view.scene.dungeon}`;
  select.value = "";
}

// ---- solving ---------------------------------------------------------------------
async function solve() {
  stopAnimation();
  showError(null);
  setPlaying(false);
  const body = request({ solver: $("solver").value, time_limit: Number($("time-limit").value) || 10 });
  const maxStates = Number($("max-states").value);
  if (maxStates > 0) body.max_states = maxStates;
  try {
    const { id } = await api("POST", "/solve", body);
    view.job = id;
    $("cancel-btn").disabled = false;
    $("solve-btn").disabled = true;
    let job;
    for (;;) {
      job = await api("GET", `/jobs/${id}`);
      setStatus(`job ${id}: ${job.status}`, "busy");
      if (["done", "failed", "cancelled"].includes(job.status)) break;
      await new Promise((r) => setTimeout(r, 200));
    }
    if (job.status !== "done") throw new Error(job.error || job.status);
    const r = job.result;
    view.result = r;
    table($("stats"), [["dungeon", r.dungeon], ["goal", r.goal], ["solver", r.solver], ["status", r.status],
      ["solved", String(r.solved)], ["cost", String(r.cost ?? "—")], ["plan length", String(r.plan.length)],
      ["expanded", r.expanded.toLocaleString()], ["generated", r.generated.toLocaleString()],
      ["stored", r.stored.toLocaleString()], ["seconds", r.seconds.toFixed(3)], ["peak MB", String(r.peak_mb)],
      ["heuristic", r.heuristic ?? "—"], ["message", r.message || "—"]]);
    await replay(r.plan);
    showPlan(r.plan);
    view.step = 0;
    render();
    setStatus(r.solved ? `solved: ${r.plan.length} steps, cost ${r.cost}` : `not solved: ${r.message}`,
      r.solved ? "ok" : "bad");
    if (r.solved) animate();
  } catch (err) {
    showError(err);
    setStatus("solve failed", "bad");
  } finally {
    view.job = null;
    $("cancel-btn").disabled = true;
    $("solve-btn").disabled = false;
  }
}

async function cancel() {
  if (view.job) await api("DELETE", `/jobs/${view.job}`).catch(showError);
}

// ---- play mode -------------------------------------------------------------------
// Key presses run one after another: each replays the actions so far plus one.
let pending = Promise.resolve();
function queue(task) { pending = pending.then(task, task); return pending; }

function setPlaying(on) {
  view.playing = on;
  $("play-toggle").textContent = on ? "Stop playing" : "Start playing";
  document.body.classList.toggle("playing", on);
}

function setupActionButtons() {
  $("action-buttons").replaceChildren(...view.scene.actions.map((name, i) => {
    const b = document.createElement("button");
    const key = keyOf(name);
    b.textContent = key ? `${key.toUpperCase()} ${name}` : name;
    b.dataset.action = name;
    b.addEventListener("click", () => queue(async () => { if (!view.playing) await startPlaying(); await act(name); }));
    return b;
  }));
}

async function startPlaying() {
  stopAnimation();
  setPlaying(true);
  await replay([]).catch(showError);
  showPlan([]);
  view.step = 0;
  render();
  setStatus("playing: use the keys or the buttons");
}

async function act(name) {
  const last = view.frames[view.frames.length - 1];
  if (last && (last.goal || last.failure)) { setStatus("the episode has ended: Reset or Backspace"); return; }
  try {
    const tried = view.actions.concat([name]);
    const data = await replay(tried);
    showPlan(view.actions);
    view.step = view.frames.length - 1;
    render();
    if (data.steps < tried.length) setStatus(data.message);
    else if (data.reached_goal) setStatus(`goal reached in ${data.steps} steps (cost ${data.cost})`);
    else if (view.frames[view.step].failure) setStatus(data.message, "bad");
    else setStatus(`${name}: ok (${data.steps} steps)`);
  } catch (err) {
    showError(err);
  }
}

async function undo() {
  if (!view.actions.length) return;
  await replay(view.actions.slice(0, -1)).catch(showError);
  showPlan(view.actions);
  view.step = view.frames.length - 1;
  render();
}

async function saveDemonstration() {
  try {
    const demo = await api("POST", "/demonstration", request({ actions: view.actions }));
    const blob = new Blob([JSON.stringify(demo, null, 1)], { type: "application/json" });
    const a = document.createElement("a");
    a.href = URL.createObjectURL(blob);
    a.download = `${view.scene.dungeon}-demonstration.json`;
    document.body.append(a);
    a.click();
    a.remove();
    setStatus(`saved a demonstration of ${demo.actions.length} actions`);
  } catch (err) {
    showError(err);
  }
}

function onKey(event) {
  if (!view.playing || event.target.matches("textarea, input, select")) return;
  const name = actionForKey(event.key);
  if (event.key === "Backspace") { event.preventDefault(); queue(undo); return; }
  if (!name || !view.scene || !view.scene.actions.includes(name)) return;
  event.preventDefault();
  queue(() => act(name));
}

// ---- start -----------------------------------------------------------------------
async function loadShipped(name) {
  if (!(name in view.shipped)) view.shipped[name] = (await api("GET", `/dungeons/${name}`)).yaml;
  $("yaml").value = view.shipped[name];
  await drawDungeon();
}

async function start() {
  const [{ dungeons }, { solvers }] = await Promise.all([api("GET", "/dungeons"), api("GET", "/solvers")]);
  $("dungeon-select").replaceChildren(...dungeons.map((d) => new Option(`${d.name} — ${d.goal ?? "inherits its goal"}`, d.name)));
  $("solver").replaceChildren(...Object.keys(solvers).map((s) => {
    const info = solvers[s], option = new Option(`${s} — ${info.description}`, s);
    if (info.unavailable) { option.disabled = true; option.text += ` (unavailable: ${info.unavailable})`; }
    return option;
  }));
  if ("astar" in solvers) $("solver").value = "astar";
  const wanted = new URLSearchParams(location.search).get("dungeon");
  const first = dungeons.some((d) => d.name === wanted) ? wanted : (dungeons.some((d) => d.name === "bridge") ? "bridge" : dungeons[0].name);
  $("dungeon-select").value = first;
  $("dungeon-select").addEventListener("change", (e) => {
    if (!e.target.value) return;  // "your dungeon": already drawn
    setPlaying(false);
    loadShipped(e.target.value);
  });
  $("upload").addEventListener("change", async (e) => {
    const file = e.target.files[0];
    if (!file) return;
    $("yaml").value = await file.text();
    setPlaying(false);
    drawDungeon();
  });
  $("draw-btn").addEventListener("click", () => { setPlaying(false); drawDungeon(); });
  $("solve-btn").addEventListener("click", solve);
  $("cancel-btn").addEventListener("click", cancel);
  $("first-btn").addEventListener("click", () => { stopAnimation(); goTo(0); });
  $("back-btn").addEventListener("click", () => { stopAnimation(); goTo(view.step - 1); });
  $("next-btn").addEventListener("click", () => { stopAnimation(); goTo(view.step + 1); });
  $("last-btn").addEventListener("click", () => { stopAnimation(); goTo(view.frames.length - 1); });
  $("play-btn").addEventListener("click", animate);
  $("scrub").addEventListener("input", (e) => { stopAnimation(); goTo(Number(e.target.value)); });
  $("play-toggle").addEventListener("click", () => (view.playing ? setPlaying(false) : startPlaying()));
  $("reset-btn").addEventListener("click", startPlaying);
  $("save-demo-btn").addEventListener("click", saveDemonstration);
  document.addEventListener("keydown", onKey);
  await loadShipped(first);
  document.body.dataset.ready = "1";
}

start().catch((err) => { showError(err); setStatus("could not reach the server", "bad"); });
