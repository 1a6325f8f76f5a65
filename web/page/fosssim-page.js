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

/// The most files one scene may name (meshes) that the page fetches or takes from the student's
/// files before it gives up and shows the loader's error; raise it for scenes of more meshes.
const kMaxNamedFiles = 64;

/// The last part of a path ("../cloth/cloth.obj" -> "cloth.obj").
const baseName = (path) => path.replace(/^.*\//, "");

/// Where the files a suite's scene names come from: the served suites (scenes/PATH), or null.
async function fetchSuiteFile(path) {
  if (path.startsWith("/")) return null;
  const response = await fetch(`scenes/${path}`);
  return response.ok ? new Uint8Array(await response.arrayBuffer()) : null;
}

FOSSSimModule().then(async (fosssim) => {
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
  // Where the files the loaded scene names come from (path -> Promise of bytes or null): the
  // served suites for a scene picked from them, the student's opened files otherwise.
  let studentFiles = new Map();  // base name -> File, the files opened together
  const fromStudentFiles = async (path) => {
    const file = studentFiles.get(baseName(path));
    return file ? new Uint8Array(await file.arrayBuffer()) : null;
  };
  let source = fromStudentFiles;

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
  /// Loads the text box's scene as `name`. A file it names that the page does not hold yet (a
  /// mesh) is asked of `source` (fetched from the suites, or the student's file of that name)
  /// and the scene loaded again; a file nobody has leaves the loader's own error on show.
  const load = async () => {
    running = false;
    energies = [];
    report.textContent = "";
    let problem = session.load(text.value, name, canvas.width, canvas.height);
    const tried = new Set();
    while (problem && tried.size < kMaxNamedFiles) {
      const missing = session.missingFile();
      if (!missing || tried.has(missing)) break;
      tried.add(missing);
      const bytes = await source(missing);
      if (bytes === null || session.addFile(missing, bytes) !== "") break;
      problem = session.load(text.value, name, canvas.width, canvas.height);
    }
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
    source = fetchSuiteFile;
    session.clearFiles();
    text.value = await fetchText(`scenes/${path}`);
    return load();
  };
  /// Opens the student's files (a FileList or array of File): the first scene among them (.xml,
  /// or .json) is loaded, and the others are the files it names, matched by their base names
  /// (a scene naming "../meshes/cloth.obj" finds an opened cloth.obj).
  const open = async (files) => {
    const all = Array.from(files);
    const scene = all.find((f) => /\.xml$/i.test(f.name)) ||
                  all.find((f) => /\.json$/i.test(f.name)) || all[0];
    if (!scene) return "";
    studentFiles = new Map(all.map((f) => [f.name, f]));
    source = fromStudentFiles;
    session.clearFiles();  // no file of an earlier opening stands in for a missing one
    name = scene.name;
    text.value = await scene.text();
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
  $("open").addEventListener("change", (event) => { open(event.target.files); });
  $("load").addEventListener("click", () => { load(); });
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
  // The picture fills the canvas's content box, inside its border: the bounding box would put
  // the cursor a border's width off and scale it by 640/642 (web.browser.drag found this).
  const pixel = (event) => {
    const box = canvas.getBoundingClientRect();
    return [(event.clientX - box.left - canvas.clientLeft) * canvas.width / canvas.clientWidth,
            (event.clientY - box.top - canvas.clientTop) * canvas.height / canvas.clientHeight];
  };
  canvas.addEventListener("mousedown", (event) => {
    if (event.button === 0 && session.press(...pixel(event))) draw();
  });
  canvas.addEventListener("mousemove", (event) => { session.move(...pixel(event)); });
  window.addEventListener("mouseup", () => { session.release(); });

  text.value = kPendulum;
  await load();
  requestAnimationFrame(frame);
  const params = new URLSearchParams(location.search);
  if (params.has("test")) {
    runTest(params, { session, pick, open, trajectory, grade, advance, draw, load, text, error,
                      canvas })
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
///   ?test=drag                          drags a particle with mouse events; its positions
///   ?test=references&scenes=..&user=..  scenes naming meshes: picked, and opened with their files
async function runTest(params, page) {
  const test = params.get("test");
  const digestLine = async (label, problem) => {
    if (problem) return `${label}\tERROR\t${problem}`;
    const bytes = page.trajectory();
    if (bytes === null) return `${label}\tERROR\t${page.session.lastError()}`;
    return `${label}\t${bytes.length}\t${await sha256(bytes)}`;
  };
  if (test === "digests") {
    const lines = [];
    for (const path of params.get("scenes").split(",")) {
      lines.push(await digestLine(path, await page.pick(path)));
    }
    return lines.join("\n");
  }
  if (test === "drag") {
    // A free particle (2 kg) at the origin and a fixed one 1 m to its right, no forces: the
    // mouse grabs the free one on the canvas and pulls it; browser_test.py checks the positions
    // against the drag spring's steps worked by hand.
    page.text.value = `<scene>
  <duration time="1"/>
  <integrator type="symplectic-euler" dt="0.01"/>
  <particle m="2" px="0" py="0" vx="0" vy="0" fixed="0"/>
  <particle m="1" px="1" py="0" vx="0" vy="0" fixed="1"/>
</scene>`;
    const problem = await page.load();
    if (problem) return problem;
    const commands = page.session.draw();
    const values = [];
    for (let i = 0; i < commands.size(); ++i) values.push(commands.get(i));
    commands.delete();
    const discs = [];  // the particles' centres in canvas pixels, in order
    for (let k = 0; k < values.length;) {
      const code = values[k], n = values[k + 1];
      if (code === 5) discs.push([values[k + 1], values[k + 2]]);
      k += [4, 5 + 2 * n, 6 + 2 * n, 14, 9, 7, 8][code];
    }
    // Canvas pixels to the client coordinates of mouse events: the canvas's content box
    // (inside its border), as a student's pointer sees the picture.
    const canvas = page.canvas, box = canvas.getBoundingClientRect();
    const client = ([x, y]) => [box.left + canvas.clientLeft + x * canvas.clientWidth / canvas.width,
                                box.top + canvas.clientTop + y * canvas.clientHeight / canvas.height];
    const mouse = (target, type, at) => target.dispatchEvent(new MouseEvent(type, {
      clientX: at[0], clientY: at[1], button: 0, buttons: 1, bubbles: true }));
    const grabbed = [discs[0][0] + 2, discs[0][1] - 1];  // within the pick distance
    const shift = [48, -36];                              // pixels: right and up
    const state = () => {
      const v = page.session.positions(), x = [];
      for (let i = 0; i < v.size(); ++i) x.push(v.get(i));
      v.delete();
      return x;
    };
    const lines = [`pixels_per_metre\t${discs[1][0] - discs[0][0]}`,
                   `discs\t${JSON.stringify(discs)}`, `shift\t${JSON.stringify(shift)}`,
                   `x0\t${JSON.stringify(state())}`];
    mouse(canvas, "mousedown", client(grabbed));
    mouse(canvas, "mousemove", client([grabbed[0] + shift[0], grabbed[1] + shift[1]]));
    for (const k of [1, 2]) {
      page.advance(1);
      lines.push(`x${k}\t${JSON.stringify(state())}`);
    }
    mouse(window, "mouseup", client([grabbed[0] + shift[0], grabbed[1] + shift[1]]));
    page.advance(1);
    lines.push(`x3\t${JSON.stringify(state())}`);
    return lines.join("\n");
  }
  if (test === "references") {
    // Scenes that name other files: picked from the suites (the files fetched from them), and
    // opened by the student together with their files, then alone (the loader's error).
    const lines = [];
    for (const path of params.get("scenes").split(",")) {
      lines.push(await digestLine(path, await page.pick(path)));
    }
    const files = [];
    for (const path of params.get("user").split(",")) {
      const response = await fetch(`scenes/${path}`);
      files.push(new File([await response.blob()], baseName(path)));
    }
    lines.push(await digestLine(`user:${files[0].name}`, await page.open(files)));
    const alone = await page.open([files[0]]);
    lines.push(`alone:${files[0].name}\t${alone.split("\n")[0]}`);
    return lines.join("\n");
  }
  if (test === "error") {
    page.text.value = params.get("scene");
    await page.load();
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
    const problem = await page.load();
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
