// The headless Chromium that the build (prerender.mjs), the benches and the
// end-to-end tests drive: Debian's package (scripts/setup.sh installs it) or
// CHROMIUM_PATH, with one set of flags — no sandbox (containers), no GPU
// (servers), and nothing the browser starts on its own (QUIC, background
// networking, component updates, sync) competing with what is timed.
export const CHROMIUM = process.env.CHROMIUM_PATH || "/usr/bin/chromium";
export const CHROMIUM_ARGS = Object.freeze([
  "--headless",
  "--no-sandbox",
  "--disable-gpu",
  "--disable-quic",
  "--no-first-run",
  "--disable-background-networking",
  "--disable-component-update",
  "--disable-sync",
]);

/** playwright-core's chromium.launch() with these (imported here: the build needs it only when Chromium is there). */
export async function launchChromium() {
  const { chromium } = await import("playwright-core");
  return chromium.launch({ executablePath: CHROMIUM, args: [...CHROMIUM_ARGS] });
}
