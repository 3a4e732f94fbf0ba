// "Copy a work receipt": the button and what it shows — the receipt text (also
// copied to the clipboard), the address that regrades it, and a QR code of
// that address for a phone. Practice (www/practice/view.js) and a SCORM
// package's page (www/lms/launch.js) both use it.

import { el } from "../dom.js";
import { lmsStyles } from "./styles.js";
import { loadQr, qrSvg } from "../practice/sheets.js";
import { encodeAttempt } from "./attempt.js";

/** Longest address put into a QR code (a version-40 code at level M holds 2,331 bytes; phones read far fewer well). */
const QR_MAX = 1200;

/**
 * The receipt's address: #/practice?receipt=… on the site (`site`: the
 * playground's page, for a package's page, which has no receipt view).
 */
export function receiptAddress(text, site = location.href) {
  const url = new URL(site);
  url.search = "";
  url.hash = `#/practice?receipt=${text}`;
  return url.href;
}

/** The button and its output; `attempt()` gives [{ id, code, answers }] when pressed. */
export function receiptBox(attempt, { site = location.href } = {}) {
  lmsStyles();
  const button = el("button", { type: "button", class: "button receipt-button" }, "Copy a work receipt");
  const out = el("div", { class: "receipt-out", hidden: true });
  const said = el("p", { class: "receipt-said", role: "status" });
  button.addEventListener("click", async () => {
    const text = encodeAttempt(attempt());
    const address = receiptAddress(text, site);
    let copied = false;
    try {
      await navigator.clipboard.writeText(text);
      copied = true;
    } catch {
      copied = false;
    }
    const field = el("textarea", { class: "receipt-text", readonly: true, rows: "3", "aria-label": "Your work receipt", spellcheck: "false" });
    field.value = text;
    const encode = address.length <= QR_MAX ? await loadQr() : null;
    out.replaceChildren(
      field,
      el("p", { class: "muted" }, "Your instructor pastes it at Practice → Check a work receipt, or opens ", el("a", { href: address, class: "receipt-link" }, "this address"), ", and sees every answer graded again."),
      encode ? qrSvg(encode, address) : el("p", { class: "muted" }, address.length > QR_MAX ? "Too long for a QR code: copy the text." : ""),
    );
    out.hidden = false;
    said.textContent = copied ? `Receipt copied (${text.length} characters).` : "Select the receipt below and copy it.";
  });
  return { button, element: el("div", { class: "receipt-box" }, said, out) };
}
