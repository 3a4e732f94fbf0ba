// The accessibility statement as a page of the site (#/accessibility, the
// footer's "Accessibility" link): what a reader can count on, the known gaps
// and how to report a problem. The full statement, with how it is tested, is
// docs/accessibility.md; keep the two saying the same.

import { el } from "./dom.js";

const SUPPORTED = [
  "Keyboard: every control, the figures' cell cursors and the image lab work without a mouse; a “Skip to the example” link comes first; the focus is always visible and never hidden under other content.",
  "Screen readers: formulas are MathML (KaTeX writes it beside each formula); numbers such as 1.87772 × 10⁻⁶ are read “1.87772 times 10 to the minus 6”; a matrix is a table; the answer line and each practice verdict are announced when they change; each figure has a description and its data as tables.",
  "Motion: with “reduce motion” set in the system, nothing scrolls smoothly, moves or animates.",
  "Colours: light and dark themes (the system's, or the Theme switch), both with WCAG AA contrast for text, labels, legends and focus rings.",
  "Zoom and small screens: the page reflows at 320 px wide and at 400 % zoom without scrolling sideways (wide formulas and matrices scroll in their own box); controls are at least 24 × 24 px.",
];

const GAPS = [
  "Checked by automated tests in Chromium only (axe-core, WCAG 2.2 AA rules; the accessibility tree through the DevTools protocol); not yet with NVDA, JAWS or VoiceOver by a person.",
  "The figures' canvases are pictures: their description and data tables carry the numbers, not every line drawn.",
  "Formulas are read as MathML: how well depends on the screen reader (NVDA with MathCAT or MathPlayer, VoiceOver and JAWS read MathML).",
];

/** The statement's view (a <section>, for <main>). */
export function statementView() {
  return el(
    "section",
    { class: "statement" },
    el("h2", { id: "statement-title", tabindex: "-1" }, "Accessibility"),
    el("p", {}, "The playground aims at WCAG 2.2 level AA, for the pages of the examples, practice, worksheets, the embed and the image lab."),
    el("h3", {}, "What works"),
    el("ul", {}, SUPPORTED.map((t) => el("li", {}, t))),
    el("h3", {}, "Known gaps"),
    el("ul", {}, GAPS.map((t) => el("li", {}, t))),
    el("h3", {}, "Report a problem"),
    el(
      "p",
      {},
      "Tell your course's instructor, or open an issue in the project's repository: the page's address (Copy link), what you did, what you expected, and your browser and assistive technology. The full statement, with how it is tested, is docs/accessibility.md in the source.",
    ),
    el("p", {}, el("a", { href: "#/" }, "← All examples")),
  );
}
