import { chromium } from "playwright-core";
import { startServer } from "./scripts/serve.mjs";
const server = await startServer({ dir: "dist", port: 0 });
const browser = await chromium.launch({ executablePath: "/usr/bin/chromium", args: ["--headless", "--no-sandbox", "--disable-gpu"] });
const idle = (page) => page.waitForFunction(() => document.body.dataset.lab === "idle", null, { timeout: 60000 });
async function pos(page, x, y) {
  await page.locator("#lab-stage .lab-canvas").scrollIntoViewIfNeeded();
  const g = await page.evaluate(async () => (await import("./lab/lab.js")).viewForTests());
  return [g.left + ((x + 0.5) * g.zoom + g.ox) * (g.w / g.cw), g.top + ((y + 0.5) * g.zoom + g.oy) * (g.h / g.ch)];
}
for (const width of [390, 1280]) {
  const page = await browser.newPage({ viewport: { width, height: 900 } });
  page.on("pageerror", (e) => console.log("PAGEERROR", e.message));
  const open = async (id) => {
    await page.goto(`${server.url}index.html#/lab`);
    await page.waitForSelector("#lab-sample");
    await page.selectOption("#lab-sample", id);
    await page.click("#lab-open-sample");
    await idle(page);
  };
  // custom kernel with an error, then a valid run
  await open("camera.png");
  await page.selectOption("#lab-family", "filters");
  await page.selectOption("#lab-kernel", "custom");
  await page.fill("#lab-custom", "1 2 1\n2 4");
  await page.screenshot({ path: `/tmp/lab14/custom-error-${width}.png`, fullPage: false });
  await page.fill("#lab-custom", "1 0 -1\n2 0 -2\n1 0 -1");
  await page.fill("#lab-divisor", "1");
  await page.click("#lab-run");
  await page.waitForFunction(() => document.body.dataset.filterShown === "custom");
  await idle(page);
  await page.screenshot({ path: `/tmp/lab14/custom-${width}.png`, fullPage: true });
  // size slider
  await page.selectOption("#lab-kernel", "mean-k");
  await page.screenshot({ path: `/tmp/lab14/meank-${width}.png` });
  // correlation
  await open("aero1.jpg");
  await page.selectOption("#lab-family", "correlation");
  await page.selectOption("#lab-template", "21");
  let [x, y] = await pos(page, 300, 200);
  await page.mouse.click(x, y);
  await page.waitForSelector("#lab-match");
  await idle(page);
  await page.focus("#lab-template-handle");
  await page.keyboard.press("Shift+ArrowRight");
  await page.waitForTimeout(800);
  await idle(page);
  await page.screenshot({ path: `/tmp/lab14/template-${width}.png`, fullPage: true });
  // fiducials
  await open("frame");
  await page.selectOption("#lab-family", "fiducials");
  await page.screenshot({ path: `/tmp/lab14/fid-start-${width}.png` });
  const truth = await page.evaluate(async () => (await import("./lab/lab.js")).truthForTests());
  const off = [[1.5, -1], [-1, 1.2], [0.8, 1.4], [-1.3, -0.7]];
  await page.uncheck("#lab-fid-refine");
  for (let k = 0; k < 4; k++) {
    [x, y] = await pos(page, truth.marks[2 * k] + off[k][0] * 2, truth.marks[2 * k + 1] + off[k][1] * 2);
    await page.mouse.click(x, y);
    await idle(page);
  }
  await page.waitForSelector("#lab-fid-fit");
  await page.screenshot({ path: `/tmp/lab14/fid-${width}.png`, fullPage: true });
  // interest with the threshold slider
  await open("left01.jpg");
  await page.selectOption("#lab-family", "interest");
  await page.click("#lab-run");
  await page.waitForFunction(() => document.body.dataset.forstnerLive === "idle" && document.body.dataset.threshold);
  await page.screenshot({ path: `/tmp/lab14/interest-${width}.png` });
  await page.close();
}
await browser.close();
await server.close();
