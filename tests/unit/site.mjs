// A small made-up site in a temp folder for the build scripts' unit tests
// (assets.test.mjs); removed when the test file ends.
import { after } from "node:test";
import fs from "node:fs";
import os from "node:os";
import path from "node:path";

const made = [];
after(() => made.forEach((dir) => fs.rmSync(dir, { recursive: true, force: true })));

/** Writes `files` ({ "path/name": text }) into a new temp folder and returns it. */
export function site(files, prefix = "site-test-") {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), prefix));
  made.push(dir);
  for (const [name, text] of Object.entries(files)) {
    fs.mkdirSync(path.dirname(path.join(dir, name)), { recursive: true });
    fs.writeFileSync(path.join(dir, name), text);
  }
  return dir;
}
