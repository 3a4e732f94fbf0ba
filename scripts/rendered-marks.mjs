// What `npm run bench` times for a performance mark of the page (or of the
// floor page): not the mark itself, which script sets as soon as the DOM
// holds the numbers, but the frame that shows them. Passed to Playwright's
// addInitScript (it runs in the page, and in every frame, before the page's
// own scripts): it wraps performance.mark, and when one of `marks` is set,
// the next animation frame queues a task, which runs once that frame's
// style, layout and paint are done (as www/app.js's afterFrame does for the
// redraw). The time is recorded in window.__benchRendered[name] and told by
// a console message "bench: <name>". Between the mark and its frame lies the
// page's first layout and whatever work was queued before it: 1–3 ms on the
// floor page, 30–60 ms on the playground (docs/BENCH-LOAD.md).
export function recordRendered(marks) {
  const rendered = (window.__benchRendered = {});
  const mark = performance.mark.bind(performance);
  performance.mark = function (name, ...rest) {
    const entry = mark(name, ...rest);
    if (marks.includes(name) && !(name in rendered)) {
      rendered[name] = null;
      requestAnimationFrame(() => {
        const channel = new MessageChannel();
        channel.port1.onmessage = () => {
          channel.port1.close();
          rendered[name] = performance.now();
          console.debug(`bench: ${name}`);
        };
        channel.port2.postMessage(null);
      });
    }
    return entry;
  };
}
