// The page: loads the scene in the text box into FOSSSim (fosssim.js, the WebAssembly build's
// WebSession), runs, pauses, steps and resets it, and paints its drawing commands
// (web/src/web_session.cpp) on the canvas as the native pictures paint the same Drawing.
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

FOSSSimModule().then((fosssim) => {
  const session = new fosssim.WebSession();
  const canvas = document.getElementById("view");
  const context = canvas.getContext("2d");
  const text = document.getElementById("scene-text");
  const error = document.getElementById("error");
  const warnings = document.getElementById("warnings");
  const status = document.getElementById("status");
  let running = false;
  let name = "scene.xml";

  const draw = () => {
    const commands = session.draw();
    const values = new Array(commands.size());
    for (let i = 0; i < values.length; ++i) values[i] = commands.get(i);
    commands.delete();
    paint(context, values);
    status.textContent = `t = ${session.time().toFixed(3)}, step ${session.steps()}`;
  };
  const load = () => {
    running = false;
    const problem = session.load(text.value, name, canvas.width, canvas.height);
    error.textContent = problem;
    warnings.textContent = problem ? "" : session.warnings();
    draw();
  };
  const advance = (count) => {
    const problem = session.step(count);
    if (problem) {
      error.textContent = problem;
      running = false;
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

  document.getElementById("open").addEventListener("change", (event) => {
    const file = event.target.files[0];
    if (!file) return;
    name = file.name;
    file.text().then((content) => { text.value = content; load(); });
  });
  document.getElementById("load").addEventListener("click", load);
  document.getElementById("run").addEventListener("click", () => { running = true; });
  document.getElementById("pause").addEventListener("click", () => { running = false; });
  document.getElementById("step").addEventListener("click", () => { running = false; advance(1); });
  document.getElementById("reset").addEventListener("click", () => {
    running = false;
    session.reset();
    draw();
  });
  text.value = kPendulum;
  load();
  window.fosssimReady = true;  // for the browser tests
  requestAnimationFrame(frame);
});
