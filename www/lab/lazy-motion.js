// The lab's motion offer ("Watch it move", motion.js) without its code on a
// lab visit: motion.js (and the example figures it mounts) is fetched with the
// first explanation that links an example, which keeps a lab visit under its
// download budget (docs/lab.md; lab_tiles.test.mjs measures it).

/**
 * The lab's motion (motion.js `watchMotion`), loaded with the first
 * explanation that links an example: a lab visit that explains no pixel does
 * not fetch it. Returns { close(), destroy() } as watchMotion does.
 */
export function lazyMotion(lab) {
  let motion = null;
  let gone = false;
  const observer = new MutationObserver(() => {
    if (lab.explain.hidden || !lab.explain.querySelector('a[href^="index.html#/"]')) return;
    observer.disconnect();
    import("./motion.js").then(({ watchMotion }) => {
      if (!gone) motion = watchMotion(lab);
    });
  });
  observer.observe(lab.explain, { childList: true, subtree: true, attributes: true, attributeFilter: ["hidden", "href"] });
  return {
    close: () => motion?.close(),
    destroy() {
      gone = true;
      observer.disconnect();
      motion?.destroy();
    },
  };
}
