// Opens a run's report.html from disk (file://) in headless Chromium with every request that
// is not a file: aborted, and checks its 3D viewer: the page loads offline with no console
// error and no network request, and for each car, following it at each of the times asked,
// the car is centred and covers more than 5 % of the viewer.
//
// A car's pixels are those of its body colour's hue: the page lists each car's colour (the
// replay material's base colour, linear RGB, `sim::replay::car_colour`); under the viewer's
// white lights a lit face keeps its hue and only changes brightness, while the ground, the
// roads, the sky and the grid are grey (saturation below 0.1).
//
// Usage: node report.mjs --html FILE --part NAME --times T1,T2,T3 --out DIR --name PREFIX
//                        [--shot FILE]
//   Screenshots: DIR/PREFIX_car<I>_<T>.png; --shot also saves the whole page's first screen
//   (following the last car at the second time, or the only one) as FILE.
import { mkdtemp, rm } from "node:fs/promises";
import { tmpdir } from "node:os";
import { join, resolve } from "node:path";
import { pathToFileURL } from "node:url";
import { chromium } from "playwright-core";

const args = Object.fromEntries(
  process.argv.slice(2).reduce((pairs, a, i, all) => {
    if (a.startsWith("--")) pairs.push([a.slice(2), all[i + 1]]);
    return pairs;
  }, []),
);
for (const key of ["html", "part", "times", "out", "name"]) {
  if (args[key] === undefined) {
    console.error(`report.mjs: missing --${key}`);
    process.exit(2);
  }
}
const times = args.times.split(",").map(Number);
// Thresholds of the check (see the header): the car covers more than this share of the
// viewer...
const MIN_COVER = 0.05;
// ...and its pixels' centroid is within this share of the viewer's width and height from
// the centre (the follow camera aims at the middle of the body's image, the centre of the
// rectangle around it: the centroid of the body's colour sits 1 to 2.5 % from it, as the
// tail's face is larger than the roof's and the wheels hide some of the sides).
const MAX_OFF_CENTRE = 0.05;
// A pixel is the car's if its saturation is above this and its hue within HUE_TOLERANCE of
// the car's (degrees): shading and sRGB encoding move a hue by a few degrees.
const MIN_SATURATION = 0.25;
const HUE_TOLERANCE = 20;

const profile = await mkdtemp(join(tmpdir(), "report-chromium-"));
const problems = [];
const blocked = [];
let context;
try {
  context = await chromium.launchPersistentContext(profile, {
    executablePath: process.env.CHROMIUM ?? "/usr/bin/chromium",
    headless: true,
    viewport: { width: 1100, height: 820 },
    args: [
      "--headless",
      "--no-sandbox",
      "--disable-gpu",
      "--no-first-run",
      "--disable-background-networking",
      "--disable-component-update",
      "--disable-sync",
      // WebGL on the CPU: Chromium no longer falls back to SwiftShader on its own.
      "--enable-unsafe-swiftshader",
    ],
  });
  await context.route("**/*", (route) => {
    const url = route.request().url();
    if (url.startsWith("file:")) return route.continue();
    blocked.push(url);
    return route.abort();
  });
  const page = context.pages()[0] ?? (await context.newPage());
  page.on("console", (m) => {
    if (m.type() === "error") problems.push(`console error: ${m.text()}`);
  });
  page.on("pageerror", (e) => problems.push(`page error: ${e.message}`));
  await page.goto(pathToFileURL(resolve(args.html)).href);
  await page.evaluate(() => window.report.ready);
  const cars = await page.evaluate((part) => {
    window.report.pause();
    window.report.setPart(part);
    window.report.camera("follow");
    return window.report.data.cars;
  }, args.part);
  if ((await page.evaluate(() => window.report.state().part)) !== args.part) {
    problems.push(`the page has no scenario '${args.part}'`);
  }
  for (const [i, car] of cars.entries()) {
    for (const t of times) {
      const cover = await page.evaluate(
        ({ i, t, colour, limits }) => {
          window.report.follow(i);
          window.report.seek(t);
          const gl = document.querySelector("#viewer canvas");
          const c = document.createElement("canvas");
          c.width = gl.width;
          c.height = gl.height;
          const ctx = c.getContext("2d");
          ctx.drawImage(gl, 0, 0);
          const px = ctx.getImageData(0, 0, c.width, c.height).data;
          const srgb = (x) => (x <= 0.0031308 ? 12.92 * x : 1.055 * x ** (1 / 2.4) - 0.055);
          const hsv = (r, g, b) => {
            const max = Math.max(r, g, b);
            const d = max - Math.min(r, g, b);
            let h = 0;
            if (d > 0) {
              if (max === r) h = ((g - b) / d) % 6;
              else if (max === g) h = (b - r) / d + 2;
              else h = (r - g) / d + 4;
            }
            return [((h * 60) + 360) % 360, max > 0 ? d / max : 0];
          };
          const [hue] = hsv(...colour.map(srgb));
          let n = 0;
          let sx = 0;
          let sy = 0;
          for (let k = 0; k < px.length; k += 4) {
            const [h, s] = hsv(px[k] / 255, px[k + 1] / 255, px[k + 2] / 255);
            const dh = Math.min(Math.abs(h - hue), 360 - Math.abs(h - hue));
            if (s > limits.saturation && dh < limits.hue) {
              const p = k / 4;
              n += 1;
              sx += p % c.width;
              sy += Math.floor(p / c.width);
            }
          }
          return {
            share: n / (c.width * c.height),
            dx: n ? sx / n / c.width - 0.5 : 1,
            dy: n ? sy / n / c.height - 0.5 : 1,
            time: window.report.state().time,
          };
        },
        { i, t, colour: car.colour, limits: { saturation: MIN_SATURATION, hue: HUE_TOLERANCE } },
      );
      const file = join(args.out, `${args.name}_car${i}_${t}.png`);
      await page.locator("#viewer").screenshot({ path: file });
      const where = `${args.name}, car ${i} (${car.node}) at ${t} s`;
      console.log(
        `${where}: covers ${(100 * cover.share).toFixed(1)} %, centroid off by ` +
          `${(100 * cover.dx).toFixed(1)} %, ${(100 * cover.dy).toFixed(1)} % -> ${file}`,
      );
      if (Math.abs(cover.time - t) > 1e-9) problems.push(`${where}: the page is at ${cover.time} s`);
      if (!(cover.share > MIN_COVER)) {
        problems.push(`${where}: the car covers ${(100 * cover.share).toFixed(1)} % of the viewer (at most 5 %)`);
      }
      if (Math.abs(cover.dx) > MAX_OFF_CENTRE || Math.abs(cover.dy) > MAX_OFF_CENTRE) {
        problems.push(`${where}: the car is off centre by ${cover.dx.toFixed(2)}, ${cover.dy.toFixed(2)} of the viewer`);
      }
    }
  }
  if (args.shot) {
    await page.evaluate(
      ({ car, t }) => {
        window.report.follow(car);
        window.report.seek(t);
      },
      { car: cars.length - 1, t: times[Math.min(1, times.length - 1)] },
    );
    await page.screenshot({ path: args.shot });
    console.log(`page screenshot: ${args.shot}`);
  }
} finally {
  await context?.close();
  await rm(profile, { recursive: true, force: true });
}
for (const url of blocked) problems.push(`the page asked the network for ${url}`);
if (problems.length > 0) {
  for (const p of problems) console.error(`report.mjs: ${p}`);
  process.exit(1);
}
console.log(`report.mjs: ${args.html} passed`);
