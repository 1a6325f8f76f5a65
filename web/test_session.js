// The page's WebSession under Node (ctest web.session): a scene with an error gives the native
// message with file and line; a valid scene loads, steps and draws its particles as discs.
//   node test_session.js path/to/fosssim.js
"use strict";
const assert = require("assert");
const FOSSSimModule = require(process.argv[2]);

FOSSSimModule().then((fosssim) => {
  const session = new fosssim.WebSession();
  const broken = "<scene>\n<duration time=\"1\"/>\n<particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixde=\"0\"/>\n</scene>\n";
  const problem = session.load(broken, "broken.xml", 640, 480);
  console.log(problem);
  assert.match(problem, /^broken\.xml:1: error: <scene>: the required element <integrator> is missing$/m);
  assert.match(problem, /^broken\.xml:3: error: <particle> 0: attribute "fixed" is missing \(the element has "fixde", which is not read: a misspelling\?\)$/m);
  assert.strictEqual(session.load("<scene>\n<duration time=\"1\">\n</scene>", "bad.xml", 640, 480),
                     "bad.xml:2: error: <duration>: not well-formed XML: this element is not " +
                     "closed, or is closed with a different name");

  const scene = `<scene>
  <duration time="1.0"/>
  <integrator type="symplectic-euler" dt="0.01"/>
  <viewport cx="0" cy="0" size="2"/>
  <simplegravity fx="0" fy="-9.81"/>
  <particle m="1" px="0" py="0" vx="0" vy="0" fixed="1"/>
  <particle m="1" px="1" py="0" vx="0" vy="0" fixed="0"/>
  <edge i="0" j="1"/>
  <springforce edge="0" k="100" l0="1" b="0"/>
</scene>`;
  assert.strictEqual(session.load(scene, "pendulum.xml", 640, 480), "");
  assert.strictEqual(session.step(10), "");
  assert.strictEqual(session.steps(), 10);
  assert.ok(Math.abs(session.time() - 0.1) < 1e-12);
  const commands = session.draw();
  const values = [];
  for (let i = 0; i < commands.size(); ++i) values.push(commands.get(i));
  commands.delete();
  // Two discs (code 5), the fixed one at the viewport's centre: (320, 240) in pixels.
  const discs = [];
  for (let k = 0; k < values.length;) {
    const code = values[k];
    const n = values[k + 1];
    const sizes = {0: 4, 1: 5 + 2 * n, 2: 6 + 2 * n, 3: 14, 4: 9, 5: 7, 6: 8};
    if (code === 5) discs.push([values[k + 1], values[k + 2]]);
    assert.ok(code in sizes, `unknown command ${code}`);
    k += sizes[code];
  }
  assert.strictEqual(discs.length, 2);
  assert.ok(Math.abs(discs[0][0] - 320) < 1e-9 && Math.abs(discs[0][1] - 240) < 1e-9, `${discs[0]}`);
  assert.ok(discs[1][0] > 320 && discs[1][1] > 240, `the free particle fell: ${discs[1]}`);
  session.reset();
  assert.strictEqual(session.steps(), 0);
  console.log("web session: ok");
});
