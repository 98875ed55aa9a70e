// Renders a vehicle-sim replay.glb in headless Chromium with <model-viewer> and checks it:
// the page serves on localhost, the model loads with the animation asked for, two screenshots
// at two animation times differ, and the console shows no error.
//
// Usage: node render.mjs --glb FILE --animation NAME --times T1,T2 --target X,Y
//                        --radius R --out DIR --name PREFIX
//   --target: the world point (m, z-up world frame, x y) the camera looks at;
//   --radius: the camera's distance (m). Screenshots: DIR/PREFIX_T.png.
import { createServer } from "node:http";
import { mkdtemp, readFile, rm, writeFile } from "node:fs/promises";
import { tmpdir } from "node:os";
import { join, dirname } from "node:path";
import { fileURLToPath } from "node:url";
import { chromium } from "playwright-core";

const here = dirname(fileURLToPath(import.meta.url));
const args = Object.fromEntries(
  process.argv.slice(2).reduce((pairs, a, i, all) => {
    if (a.startsWith("--")) pairs.push([a.slice(2), all[i + 1]]);
    return pairs;
  }, []),
);
for (const key of ["glb", "animation", "times", "target", "radius", "out", "name"]) {
  if (args[key] === undefined) {
    console.error(`render.mjs: missing --${key}`);
    process.exit(2);
  }
}
const times = args.times.split(",").map(Number);
const [tx, ty] = args.target.split(",").map(Number);
const radius = Number(args.radius);

const files = {
  "/": ["text/html", join(here, "page.html")],
  "/model-viewer.min.js": [
    "text/javascript",
    join(here, "node_modules/@google/model-viewer/dist/model-viewer.min.js"),
  ],
  "/replay.glb": ["model/gltf-binary", args.glb],
};
const server = createServer(async (req, res) => {
  const entry = files[req.url.split("?")[0]];
  if (req.url === "/favicon.ico") {
    res.writeHead(204).end();
    return;
  }
  if (!entry) {
    res.writeHead(404).end();
    return;
  }
  res.writeHead(200, { "content-type": entry[0] });
  res.end(await readFile(entry[1]));
});
await new Promise((ok) => server.listen(0, "127.0.0.1", ok));
const url = `http://127.0.0.1:${server.address().port}/`;

const profile = await mkdtemp(join(tmpdir(), "replay-chromium-"));
const problems = [];
let context;
try {
  context = await chromium.launchPersistentContext(profile, {
    executablePath: process.env.CHROMIUM ?? "/usr/bin/chromium",
    headless: true,
    viewport: { width: 960, height: 540 },
    args: [
      "--headless",
      "--no-sandbox",
      "--disable-gpu",
      "--disable-quic",
      "--no-first-run",
      "--disable-background-networking",
      "--disable-component-update",
      "--disable-sync",
      // WebGL on the CPU: Chromium no longer falls back to SwiftShader on its own.
      "--enable-unsafe-swiftshader",
    ],
  });
  const page = context.pages()[0] ?? (await context.newPage());
  page.on("console", (m) => {
    if (m.type() === "error") problems.push(`console error: ${m.text()}`);
  });
  page.on("pageerror", (e) => problems.push(`page error: ${e.message}`));
  page.on("requestfailed", (r) => problems.push(`request failed: ${r.url()}`));
  await page.goto(url, { waitUntil: "load" });
  // glTF is y-up: (x, y, z) = world (y, z, x).
  const loaded = await page.evaluate(
    async ({ animation, target, orbitRadius }) => {
      const mv = document.getElementById("viewer");
      await customElements.whenDefined("model-viewer");
      const load = new Promise((ok, fail) => {
        mv.addEventListener("load", ok, { once: true });
        mv.addEventListener("error", (e) => fail(new Error(`model-viewer: ${e.detail?.type}`)), {
          once: true,
        });
      });
      mv.src = "/replay.glb";
      await load;
      mv.cameraTarget = target;
      mv.cameraOrbit = `-35deg 65deg ${orbitRadius}m`;
      mv.fieldOfView = "30deg";
      mv.minCameraOrbit = "auto auto 0m";
      mv.maxCameraOrbit = `auto auto ${4 * orbitRadius}m`;
      mv.jumpCameraToGoal();
      mv.animationName = animation;
      mv.pause();
      await mv.updateComplete;
      mv.currentTime = 0;
      await new Promise((ok) => requestAnimationFrame(() => requestAnimationFrame(ok)));
      return { animations: mv.availableAnimations, duration: mv.duration };
    },
    { animation: args.animation, target: `${ty}m 0m ${tx}m`, orbitRadius: radius },
  );
  if (!loaded.animations.includes(args.animation)) {
    problems.push(`no animation '${args.animation}' in ${loaded.animations.join(", ")}`);
  }
  const shots = [];
  for (const t of times) {
    await page.evaluate(async (time) => {
      const mv = document.getElementById("viewer");
      mv.currentTime = time;
      // Two frames: model-viewer renders the new pose on the next one.
      await new Promise((ok) => requestAnimationFrame(() => requestAnimationFrame(ok)));
      await new Promise((ok) => setTimeout(ok, 300));
    }, t);
    const png = await page.screenshot();
    const file = join(args.out, `${args.name}_${t}.png`);
    await writeFile(file, png);
    shots.push({ t, png, file });
  }
  console.log(
    `${args.glb}: animations ${loaded.animations.join(", ")}; '${args.animation}' lasts ` +
      `${loaded.duration.toFixed(2)} s; screenshots ${shots.map((s) => s.file).join(", ")}`,
  );
  for (let i = 1; i < shots.length; i++) {
    if (shots[i].png.equals(shots[0].png)) {
      problems.push(`the screenshots at ${shots[0].t} s and ${shots[i].t} s are identical`);
    }
  }
} finally {
  await context?.close();
  server.close();
  await rm(profile, { recursive: true, force: true });
}
if (problems.length > 0) {
  for (const p of problems) console.error(`render.mjs: ${p}`);
  process.exit(1);
}
