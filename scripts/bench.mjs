// npm run bench (scripts/bench.sh): the page as a student's browser meets it
// (benchmarks, not tests) — scripts/bench-load.mjs measures, for every example
// of the catalog: the gzipped bytes of wasm + JS + CSS on the critical path and
// in all, navigation → first solution beside a floor page, the same on a
// throttled phone profile, and input change → redrawn figure
// (docs/BENCH-LOAD.md says what each column means).
//   node scripts/bench.mjs [--quick] [--example ID ...] [--runs 9] [--json FILE] …
//   node scripts/bench.mjs --lab      the image lab's operators (scripts/bench_lab.mjs)
const args = process.argv.slice(2);
if (args.includes("--lab")) {
  await import("./bench_lab.mjs");
  process.exit(0);
}
await import("./bench-load.mjs");
