// Hooks for the end-to-end tests: attributes on <body> that only the tests read
// (what a view drew, how many times, which state it holds). The tests set
// globalThis.__playgroundTest before the page's scripts run (tests/e2e/harness.mjs
// open(): context.addInitScript); a student's page never writes them.
// Attributes the CSS or assistive technology read (data-status …) are not hooks:
// the page writes those itself.

/** True when the page runs under the end-to-end tests. */
export const testing = globalThis.__playgroundTest === true;

/** Sets <body data-NAME> to String(value) under the tests; nothing otherwise. */
export function testHook(name, value) {
  if (testing) document.body.dataset[name] = String(value);
}

/** Sets (or, with null, removes) an element's data-NAME under the tests; nothing otherwise. */
export function testData(node, name, value) {
  if (!testing || !node?.dataset) return;
  if (value === null || value === undefined) delete node.dataset[name];
  else node.dataset[name] = String(value);
}
