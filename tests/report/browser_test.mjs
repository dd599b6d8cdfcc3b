// The report in a real browser: runs a small sweep (with --images) and a render --error-map
// --json, makes their report, opens it by file:// URL in Debian's headless Chromium driven
// by playwright-core, and checks what a reader relies on: every picture and plot loads,
// a plot point leads to its setting, the slider moves, the zoom scales, the tables sort
// both ways, a sweep of three lights shows each light's figures and debug buffers, nothing
// fails in the console or the network, and the pages read without JavaScript. Screenshots go to OUT/screenshots for a person to look at.
//
// node browser_test.mjs SHADOWLAB OUT    (CHROMIUM overrides /usr/bin/chromium)
import assert from "node:assert/strict";
import { execFileSync } from "node:child_process";
import { existsSync, mkdirSync, readdirSync, readFileSync, rmSync } from "node:fs";
import path from "node:path";
import { pathToFileURL } from "node:url";
import { chromium } from "playwright-core";

const [shadowlab, out] = process.argv.slice(2);
if (!shadowlab || !out) throw new Error("usage: node browser_test.mjs SHADOWLAB OUT");
const executablePath = process.env.CHROMIUM || "/usr/bin/chromium";
if (!existsSync(executablePath)) throw new Error(`no Chromium at ${executablePath} (apt-get install chromium)`);

rmSync(out, { recursive: true, force: true });
const results = path.join(out, "results"), site = path.join(out, "site"), shots = path.join(out, "screenshots");
for (const dir of [results, shots]) mkdirSync(dir, { recursive: true });

function run(...args) {
  execFileSync(shadowlab, args, { stdio: ["ignore", "ignore", "inherit"] });
}

// Two techniques at two resolutions each: four settings, each with its pictures.
const size = ["--width", "160", "--height", "100"];
run("sweep", "sphere-box", "--technique", "shadow-map,pcss", "--param", "resolution=256,1024", ...size,
    "--light-radius", "0.5", "--threads", "1", "--runs", "1", "--warmup", "0", "--images", "--out", results);
// The render under the sweep's conditions (size and light radius), so that the report files
// it with the sweep, on one scene page.
run("render", "sphere-box", "--technique", "shadow-map", ...size, "--light-radius", "0.5", "-o", path.join(results, "render.png"),
    "--error-map", path.join(results, "render-error.png"), "--json", path.join(results, "render.json"),
    "--debug-buffers", path.join(results, "render-debug"));
// A scene of three lights (a point, a spot and a sun): each light's figures and debug buffers.
const lightsScene = path.join(path.dirname(new URL(import.meta.url).pathname), "../../assets/scenes/many-lights/three-lights.json");
run("sweep", lightsScene, "--technique", "shadow-map,shadow-volume", "--param", "resolution=64,512", "--width", "96",
    "--height", "60", "--threads", "1", "--runs", "1", "--warmup", "0", "--images", "--out", results);
const lightsJson = path.join(results, "three-lights-shadow-map+shadow-volume.json");
run("report", path.join(results, "sphere-box-shadow-map+pcss.json"), path.join(results, "render.json"), lightsJson,
    "--out", site);

const problems = [];   // console errors, page errors and failed requests, on any page
function watch(page) {
  page.on("console", (message) => { if (message.type() === "error") problems.push(`console: ${message.text()}`); });
  page.on("pageerror", (error) => problems.push(`page error: ${error.message}`));
  page.on("requestfailed", (request) => problems.push(`failed: ${request.url()} (${request.failure()?.errorText})`));
}

const url = (file) => pathToFileURL(path.join(site, file)).href;

// Every <img> decoded with a size, and every plot drawn with a point per table row.
async function checkPictures(page) {
  const broken = await page.$$eval("img", (images) =>
    images.filter((img) => !img.complete || img.naturalWidth === 0).map((img) => img.getAttribute("src")));
  assert.deepEqual(broken, [], `pictures that did not load on ${page.url()}`);
  for (const plot of await page.$$(".plot svg")) {
    const box = await plot.boundingBox();
    assert.ok(box && box.width > 100 && box.height > 50, "a plot is drawn");
  }
}

async function columnValues(page, table, column) {
  return table.$$eval(`tbody tr td:nth-child(${column + 1})`,
                      (cells) => cells.map((cell) => Number(cell.dataset.value)));
}

// The sweep of three lights: its table has each light's misclassified % and RMS, equal to
// the JSON's, sorts by them, and fits the page; a setting's page has a column of figures per
// light and each light's debug buffers under its name.
async function checkLights(page) {
  const rows = JSON.parse(readFileSync(lightsJson, "utf8")).rows;
  await page.goto(url("scene-three-lights.html"));
  const table = await page.$("table.sortable");
  const headers = (await table.$$eval("thead th", (cells) => cells.map((cell) => cell.textContent.trim())));
  const first = headers.indexOf("light 0 misclassified %");
  assert.deepEqual(headers.slice(first), ["light 0 misclassified %", "light 0 RMS", "light 1 misclassified %",
                                          "light 1 RMS", "light 2 misclassified %", "light 2 RMS"]);
  for (let light = 0; light < 3; ++light) {
    const expected = rows.map((row) => [row.lights[light].errors.misclassified_percent, row.lights[light].errors.rms]);
    const shown = await Promise.all([0, 1].map((k) => columnValues(page, table, first + 2 * light + k)));
    assert.deepEqual(expected.map(([m]) => m), shown[0], `light ${light}'s misclassified % as in the JSON`);
    assert.deepEqual(expected.map(([, rms]) => rms), shown[1], `light ${light}'s RMS as in the JSON`);
  }
  assert.ok(rows[0].lights.some((light) => light.errors.misclassified > 0), "the coarse map errs on a light");
  const rmsColumn = first + 3;   // light 1 RMS
  const header = (await table.$$("thead th"))[rmsColumn];
  await (await header.$("button")).click();
  await (await header.$("button")).click();
  const descending = await columnValues(page, table, rmsColumn);
  assert.deepEqual(descending, [...descending].sort((a, b) => b - a), "sorted by light 1's RMS, descending");
  assert.ok(await page.evaluate(() => document.documentElement.scrollWidth <= window.innerWidth),
            "the wide table scrolls, not the page");
  await page.screenshot({ path: path.join(shots, "scene-three-lights.png"), fullPage: true });

  const settingPage = "three-lights-shadow-map+shadow-volume-setting-0.html";
  await page.goto(url(settingPage));
  await checkPictures(page);
  const columns = await page.$$eval(".figures-table thead th", (cells) => cells.map((cell) => cell.textContent));
  assert.deepEqual(columns, ["every light", "light 0", "light 1", "light 2"]);
  const misclassified = await page.$$eval(".figures-table tbody tr", (trs) =>
    trs.filter((tr) => tr.cells[0].textContent === "misclassified %")
       .map((tr) => Array.from(tr.cells).slice(1).map((cell) => Number(cell.dataset.value)))[0]);
  assert.deepEqual(misclassified, [rows[0].errors.misclassified_percent,
                                   ...rows[0].lights.map((light) => light.errors.misclassified_percent)]);
  const headings = await page.$$eval("h3", (hs) => hs.map((h) => h.textContent));
  assert.deepEqual(headings, ["light 0", "light 1", "light 2"], "a heading per light over its debug buffers");
  const underLight2 = await page.$$eval("h3 ~ .figures:last-of-type img.debug", (imgs) => imgs.map((img) => img.getAttribute("src")));
  assert.ok(underLight2.length > 0 && underLight2.every((src) => src.includes("/light2/")), `light 2's buffers: ${underLight2}`);
  await page.screenshot({ path: path.join(shots, "setting-three-lights.png"), fullPage: true });
}

const browser = await chromium.launch({ executablePath });
try {
  const page = await browser.newPage({ viewport: { width: 1200, height: 900 } });
  watch(page);

  // Every page of the site loads its pictures and plots.
  const pages = readdirSync(site).filter((name) => name.endsWith(".html"));
  assert.equal(pages.length, 1 + 2 + 4 + 1 + 3,
               `index, two scenes, four sweep settings, one render and three settings of three lights: ${pages}`);
  for (const name of pages) {
    await page.goto(url(name));
    await checkPictures(page);
  }

  // The index links down to the scene.
  await page.goto(url("index.html"));
  await page.screenshot({ path: path.join(shots, "index.png"), fullPage: true });
  await page.locator('a[href="scene-sphere-box.html"]').first().click();
  assert.match(page.url(), /scene-sphere-box\.html$/);
  const points = await page.$$(".plot svg a circle.point");
  assert.equal(points.length, 4 + 1, "a linked point per row: four sweep settings and the render");
  await page.screenshot({ path: path.join(shots, "scene.png"), fullPage: true });

  // Sorting: by median ms, ascending then descending.
  const table = await page.$("table.sortable");
  const medianColumn = 3;
  const header = (await table.$$("thead th"))[medianColumn];
  assert.equal((await header.textContent()).trim(), "median ms");
  await (await header.$("button")).click();
  const ascending = await columnValues(page, table, medianColumn);
  assert.deepEqual(ascending, [...ascending].sort((a, b) => a - b), "ascending after one click");
  assert.equal(await header.getAttribute("aria-sort"), "ascending");
  await (await header.$("button")).click();
  const descending = await columnValues(page, table, medianColumn);
  assert.deepEqual(descending, [...ascending].sort((a, b) => b - a), "descending after a second click");
  assert.notDeepEqual(ascending, descending, "the sweep's times differ, so the order must change");

  // A plot point leads to its setting's page.
  const link = await page.$(".plot svg a");
  const href = await link.getAttribute("href");
  await Promise.all([page.waitForURL(`**/${href}`), link.click()]);
  await checkPictures(page);
  await page.screenshot({ path: path.join(shots, "setting.png"), fullPage: true });

  // The slider shows the technique's image left of the split, the reference right of it.
  const before = page.locator(".slider-before");
  await page.locator(".slider").waitFor({ state: "visible" });
  const clipAtStart = await before.evaluate((img) => getComputedStyle(img).clipPath);
  await page.locator(".slider-split").fill("20");
  const clipMoved = await before.evaluate((img) => getComputedStyle(img).clipPath);
  assert.notEqual(clipMoved, clipAtStart, "moving the slider changes the clip");
  assert.match(clipMoved, /inset\(0(px)? 80%/, "at 20 the image keeps its left 20%");
  await page.screenshot({ path: path.join(shots, "setting-slider.png"), fullPage: true });

  // The zoom scales the pictures in whole pixels.
  const image = page.locator(".figures img.pixels").first();
  const naturalWidth = await image.evaluate((img) => img.naturalWidth);
  await page.click("label[for=zoom-4]");
  assert.equal(Math.round((await image.boundingBox()).width), 4 * naturalWidth, "4x zoom");
  assert.equal(await image.evaluate((img) => getComputedStyle(img).imageRendering), "pixelated");
  await page.screenshot({ path: path.join(shots, "setting-zoom-4.png") });

  // Without JavaScript: no slider, but the pictures side by side and the tables.
  const plain = await browser.newPage({ javaScriptEnabled: false, viewport: { width: 1200, height: 900 } });
  watch(plain);
  await plain.goto(page.url());
  assert.equal(await plain.locator(".slider").isVisible(), false, "the slider needs the script");
  assert.ok((await plain.$$(".figures img.pixels")).length >= 3, "image, reference and error map");
  await checkPictures(plain);
  await plain.screenshot({ path: path.join(shots, "setting-without-javascript.png"), fullPage: true });

  await checkLights(page);

  assert.deepEqual(problems, [], "no console errors and no failed requests");
  console.log(`report browser test: ${pages.length} pages checked; screenshots in ${shots}`);
} finally {
  await browser.close();
}
