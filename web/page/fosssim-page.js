// The page: loads the scene in the text box (picked from the repository's suites, opened or
// pasted, edited at will) into FOSSSim (fosssim.js, the WebAssembly build's WebSession), runs,
// pauses, steps and resets it, paints its drawing commands (web/src/web_session.cpp) on the
// canvas as the native pictures paint the same Drawing, lets the mouse drag particles, plots the
// energy, downloads the trajectory (the -o file) and grades an uploaded one (the -i report).
// With ?test=... it runs one of the browser tests of web/browser_test.py and writes the result
// into <pre id="test-result"> (docs/web.md, "Tests in a real browser").
"use strict";

const kPendulum = `<scene>
  <duration time="5.0"/>
  <integrator type="implicit-euler" dt="0.01"/>
  <simplegravity fx="0.0" fy="-9.81"/>
  <particle m="1" px="0" py="0" vx="0" vy="0" fixed="1"/>
  <particle m="1" px="1" py="0" vx="0" vy="0" fixed="0"/>
  <particle m="1" px="2" py="0" vx="0" vy="0" fixed="0"/>
  <edge i="0" j="1"/>
  <edge i="1" j="2"/>
  <springforce edge="0" k="1000" l0="1" b="0"/>
  <springforce edge="1" k="1000" l0="1" b="0"/>
</scene>
`;

function rgb(values, k) {
  const c = (x) => Math.round(255 * Math.min(1, Math.max(0, x)));
  return `rgb(${c(values[k])},${c(values[k + 1])},${c(values[k + 2])})`;
}

/// Paints drawing commands (see Command in web_session.cpp); returns nothing.
function paint(context, values) {
  let k = 0;
  const path = (n, at) => {
    context.beginPath();
    for (let i = 0; i < n; ++i) {
      const x = values[at + 2 * i], y = values[at + 2 * i + 1];
      if (i === 0) context.moveTo(x, y); else context.lineTo(x, y);
    }
  };
  while (k < values.length) {
    const code = values[k];
    if (code === 0) {  // background
      context.fillStyle = rgb(values, k + 1);
      context.fillRect(0, 0, context.canvas.width, context.canvas.height);
      k += 4;
    } else if (code === 1) {  // region
      const n = values[k + 1];
      path(n, k + 2);
      context.closePath();
      context.fillStyle = rgb(values, k + 2 + 2 * n);
      context.fill();
      k += 5 + 2 * n;
    } else if (code === 2) {  // polyline
      const n = values[k + 1];
      context.lineWidth = values[k + 2];
      path(n, k + 3);
      context.strokeStyle = rgb(values, k + 3 + 2 * n);
      context.lineCap = "round";
      context.lineJoin = "round";
      context.stroke();
      k += 6 + 2 * n;
    } else if (code === 3) {  // triangle
      path(3, k + 1);
      context.closePath();
      context.fillStyle = rgb(values, k + 7);
      context.fill();
      if (values[k + 10] > 0) {
        context.lineWidth = values[k + 10];
        context.strokeStyle = rgb(values, k + 11);
        context.stroke();
      }
      k += 14;
    } else if (code === 4) {  // capsule
      context.beginPath();
      context.moveTo(values[k + 1], values[k + 2]);
      context.lineTo(values[k + 3], values[k + 4]);
      context.lineWidth = 2 * values[k + 5];
      context.lineCap = "round";
      context.strokeStyle = rgb(values, k + 6);
      context.stroke();
      k += 9;
    } else if (code === 5) {  // disc
      context.beginPath();
      context.arc(values[k + 1], values[k + 2], values[k + 3], 0, 2 * Math.PI);
      context.fillStyle = rgb(values, k + 4);
      context.fill();
      k += 7;
    } else if (code === 6) {  // ring
      context.beginPath();
      context.arc(values[k + 1], values[k + 2], values[k + 3], 0, 2 * Math.PI);
      context.lineWidth = values[k + 4];
      context.strokeStyle = rgb(values, k + 5);
      context.stroke();
      k += 8;
    } else {
      throw new Error(`unknown drawing command ${code} at ${k}`);
    }
  }
}

/// Plots the energies (kinetic, potential, total: one row of three per state) on `canvas`.
function plotEnergy(canvas, rows) {
  const context = canvas.getContext("2d");
  const w = canvas.width, h = canvas.height, margin = 4;
  context.fillStyle = "#fff";
  context.fillRect(0, 0, w, h);
  if (rows.length < 2) return;
  let low = Infinity, high = -Infinity;
  for (const row of rows) for (const e of row) { low = Math.min(low, e); high = Math.max(high, e); }
  if (!(high > low)) { high = low + 1; low -= 1; }
  const colors = ["#1f77b4", "#ff7f0e", "#222"];
  for (let k = 0; k < 3; ++k) {
    context.beginPath();
    rows.forEach((row, i) => {
      const x = margin + (w - 2 * margin) * i / (rows.length - 1);
      const y = h - margin - (h - 2 * margin) * (row[k] - low) / (high - low);
      if (i === 0) context.moveTo(x, y); else context.lineTo(x, y);
    });
    context.strokeStyle = colors[k];
    context.lineWidth = 1.5;
    context.stroke();
  }
}

/// SHA-256 of bytes as lowercase hex, as the regression manifest records trajectories.
async function sha256(bytes) {
  const digest = new Uint8Array(await crypto.subtle.digest("SHA-256", bytes));
  return Array.from(digest, (b) => b.toString(16).padStart(2, "0")).join("");
}

async function fetchText(url) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url}: HTTP ${response.status}`);
  return response.text();
}

FOSSSimModule().then((fosssim) => {
  const session = new fosssim.WebSession();
  const $ = (id) => document.getElementById(id);
  const canvas = $("view");
  const context = canvas.getContext("2d");
  const text = $("scene-text");
  const error = $("error");
  const warnings = $("warnings");
  const status = $("status");
  const report = $("grade-report");
  let running = false;
  let name = "scene.xml";
  let energies = [];

  const vector = (v) => {
    const values = new Array(v.size());
    for (let i = 0; i < values.length; ++i) values[i] = v.get(i);
    v.delete();
    return values;
  };
  const draw = () => {
    paint(context, vector(session.draw()));
    status.textContent = `t = ${session.time().toFixed(3)}, step ${session.steps()}`;
    plotEnergy($("energy"), energies);
  };
  const recordEnergy = () => {
    const e = vector(session.energy());
    if (e.length === 3) energies.push(e);
  };
  const load = () => {
    running = false;
    energies = [];
    report.textContent = "";
    const problem = session.load(text.value, name, canvas.width, canvas.height);
    error.textContent = problem;
    warnings.textContent = problem ? "" : session.warnings();
    recordEnergy();
    draw();
    return problem;
  };
  const advance = (count) => {
    for (let k = 0; k < count && !session.finished(); ++k) {
      const problem = session.step(1);
      if (problem) {
        error.textContent = problem;
        running = false;
        break;
      }
      recordEnergy();
    }
    draw();
  };
  const frame = () => {
    if (running) {
      advance(1);
      if (session.finished()) running = false;
    }
    requestAnimationFrame(frame);
  };
  /// Loads a scene of the repository's suites (a path listed in scenes/index.json).
  const pick = async (path) => {
    name = path;
    text.value = await fetchText(`scenes/${path}`);
    return load();
  };
  /// The loaded scene's trajectory file (the bytes of FOSSSim -s SCENE -d 0 -o OUT), or null.
  const trajectory = () => {
    const bytes = session.trajectory();
    if (bytes === null) error.textContent = session.lastError();
    return bytes;
  };
  /// Grades an uploaded trajectory (a File or Blob) against the loaded scene: the file input's
  /// handler, and what the grading test feeds its bytes through.
  const grade = async (file) => {
    const bytes = new Uint8Array(await file.arrayBuffer());
    const outcome = session.grade(bytes, file.name || "trajectory.bin");
    const problem = outcome.problem && !outcome.problem.endsWith("\n") ? outcome.problem + "\n"
                                                                       : outcome.problem;
    report.textContent = outcome.report + problem +
        (outcome.passed ? "verdict: passed" : "verdict: failed");
    report.dataset.passed = outcome.passed ? "1" : "0";
    return outcome;
  };

  fetchText("scenes/index.json").then((index) => {
    const picker = $("picker");
    for (const path of JSON.parse(index)) picker.add(new Option(path, path));
  }).catch((problem) => { warnings.textContent = `no scene index: ${problem.message}`; });
  $("picker").addEventListener("change", (event) => {
    if (event.target.value) pick(event.target.value).catch((p) => { error.textContent = p.message; });
  });
  $("open").addEventListener("change", (event) => {
    const file = event.target.files[0];
    if (!file) return;
    name = file.name;
    file.text().then((content) => { text.value = content; load(); });
  });
  $("load").addEventListener("click", load);
  $("run").addEventListener("click", () => { running = true; });
  $("pause").addEventListener("click", () => { running = false; });
  $("step").addEventListener("click", () => { running = false; advance(1); });
  $("reset").addEventListener("click", () => {
    running = false;
    session.reset();
    energies = [];
    recordEnergy();
    draw();
  });
  $("download").addEventListener("click", () => {
    const bytes = trajectory();
    if (bytes === null) return;
    const link = document.createElement("a");
    link.href = URL.createObjectURL(new Blob([bytes], { type: "application/octet-stream" }));
    link.download = name.replace(/^.*\//, "").replace(/\.xml$/, "") + ".bin";
    link.click();
    URL.revokeObjectURL(link.href);
  });
  $("upload").addEventListener("change", (event) => {
    const file = event.target.files[0];
    if (file) grade(file);
  });
  // Dragging: the native window's ctrl + left drag, here any left drag on a particle.
  const pixel = (event) => {
    const box = canvas.getBoundingClientRect();
    return [(event.clientX - box.left) * canvas.width / box.width,
            (event.clientY - box.top) * canvas.height / box.height];
  };
  canvas.addEventListener("mousedown", (event) => {
    if (event.button === 0 && session.press(...pixel(event))) draw();
  });
  canvas.addEventListener("mousemove", (event) => { session.move(...pixel(event)); });
  window.addEventListener("mouseup", () => { session.release(); });

  text.value = kPendulum;
  load();
  requestAnimationFrame(frame);
  const params = new URLSearchParams(location.search);
  if (params.has("test")) {
    runTest(params, { session, pick, trajectory, grade, advance, draw, load, text, error, canvas })
      .catch((problem) => `test failed: ${problem.message}`)
      .then((result) => {
        const out = $("test-result");
        out.textContent = result;
        out.dataset.done = "1";
      });
  } else {
    // ?scene=PATH[&steps=K]: open a scene of the suites (a link to share), K steps taken.
    if (params.has("scene")) {
      const path = params.get("scene");
      pick(path).then(() => {
        $("picker").value = path;
        advance(Number(params.get("steps") || 0));
      }).catch((problem) => { error.textContent = problem.message; });
    }
    if ("serviceWorker" in navigator) navigator.serviceWorker.register("service-worker.js");
  }
  window.fosssimReady = true;
});

/// The browser tests' page side (web/browser_test.py reads #test-result from the dumped DOM).
///   ?test=digests&scenes=a.xml,b.xml   one line per scene: path, bytes, SHA-256 of its trajectory
///   ?test=error&name=N&scene=TEXT       the error text of loading TEXT named N, as the page shows it
///   ?test=grade&scene=P&upload=URL      the report of grading the file at URL against scene P
///   ?test=picture&scene=P&steps=K       K steps, then only the canvas is shown (a screenshot)
///   ?test=timing&url=U                  the page's load time and the time per step of scene U
async function runTest(params, page) {
  const test = params.get("test");
  if (test === "digests") {
    const lines = [];
    for (const path of params.get("scenes").split(",")) {
      const problem = await page.pick(path);
      if (problem) { lines.push(`${path}\tERROR\t${problem}`); continue; }
      const bytes = page.trajectory();
      if (bytes === null) { lines.push(`${path}\tERROR\t${page.session.lastError()}`); continue; }
      lines.push(`${path}\t${bytes.length}\t${await sha256(bytes)}`);
    }
    return lines.join("\n");
  }
  if (test === "error") {
    page.text.value = params.get("scene");
    page.load();
    return page.error.textContent;
  }
  if (test === "grade") {
    const problem = await page.pick(params.get("scene"));
    if (problem) return problem;
    const response = await fetch(params.get("upload"));
    const file = new File([await response.blob()], params.get("upload").replace(/^.*\//, ""));
    await page.grade(file);  // the file input's own handler
    return document.getElementById("grade-report").textContent;
  }
  if (test === "picture") {
    const problem = await page.pick(params.get("scene"));
    if (problem) return problem;
    page.advance(Number(params.get("steps") || 0));
    document.body.classList.add("picture-only");
    return `t=${page.session.time()}`;
  }
  if (test === "timing") {
    // Not a test: the figures of docs/web.md, "Speed" (browser_test.py timing).
    const ready = performance.now();  // milliseconds since the navigation started
    page.text.value = await fetchText(params.get("url"));
    const problem = page.load();
    if (problem) return problem;
    const start = performance.now();
    let steps = 0;
    while (!page.session.finished()) {
      const failure = page.session.step(1);
      if (failure) return failure;
      ++steps;
    }
    const elapsed = performance.now() - start;
    const figures = `load_ms\t${ready.toFixed(0)}\nsteps\t${steps}\n` +
                    `ms_per_step\t${(elapsed / steps).toFixed(3)}`;
    await fetch("timing", { method: "POST", body: figures });  // browser_test.py timing
    return figures;
  }
  throw new Error(`unknown test ${test}`);
}
