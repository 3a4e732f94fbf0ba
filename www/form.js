// The input form, built from a catalog entry's fields (docs/API.md, `Field`).
// Every field is edited as text: the core parses and validates the texts
// (parse_inputs), so the page never second-guesses the rules.

import { el, idPart } from "./dom.js";

/** Lines shown by a textarea at least / at most before it scrolls. */
const TEXTAREA_MIN_ROWS = 2;
const TEXTAREA_MAX_ROWS = 12;

/**
 * Bounds this far out only guard against nonsense (the core still checks
 * them and says so); the help line leaves them out.
 */
const GUARD_BOUND = 1e6;

/** The text a field starts with (the seed's value); matrices one row per line. */
export function defaultText(field) {
  const text = field.default_text ?? (field.default == null ? "" : String(field.default));
  if (field.kind === "matrix" || field.kind === "points") {
    return text
      .split(";")
      .map((row) => row.trim())
      .join("\n");
  }
  return text;
}

function describeField(field) {
  const parts = [];
  if (field.kind === "number" || field.kind === "integer") {
    if (field.kind === "integer") parts.push("whole number");
    if (field.min != null && Math.abs(field.min) < GUARD_BOUND) parts.push(`${field.min_exclusive ? ">" : "≥"} ${field.min}`);
    if (field.max != null && Math.abs(field.max) < GUARD_BOUND) parts.push(`≤ ${field.max}`);
    return parts.join(", ");
  } else if (field.kind === "vector") {
    parts.push("numbers separated by commas or spaces");
    if (field.max_len != null) parts.push(`at most ${field.max_len}`);
  } else if (field.kind === "matrix") {
    if (field.rows != null && field.cols != null) parts.push(`${field.rows} × ${field.cols}`);
    parts.push("one row per line (or rows separated by ;), numbers by spaces or commas");
  } else if (field.kind === "points") {
    if (field.point_len != null) parts.push(`${field.point_len} numbers per row`);
    parts.push("one point per line (or separated by ;)");
    if (field.max_len != null) parts.push(`at most ${field.max_len} rows`);
  }
  return parts.join("; ");
}

function textareaRows(field, text) {
  const lines = String(text).split("\n").length;
  const wanted = Math.max(lines, field.rows ?? 0, TEXTAREA_MIN_ROWS);
  return Math.min(wanted, TEXTAREA_MAX_ROWS);
}

/**
 * Builds the form.
 * @param {object} entry  a catalog entry (status "ready")
 * @param {(key: string) => void} onInput  called on every edit
 */
export function buildForm(entry, onInput) {
  const prefix = `f-${idPart(entry.id)}`;
  const form = el("form", { class: "input-form", novalidate: true, "aria-label": `Inputs of ${entry.title}` });
  form.addEventListener("submit", (e) => e.preventDefault());
  const controls = new Map();

  for (const field of entry.inputs) {
    const key = field.key;
    const inputId = `${prefix}-${idPart(key)}`;
    const helpId = `${inputId}-help`;
    const errId = `${inputId}-error`;
    const seedText = defaultText(field);
    const rules = describeField(field);
    const help = el(
      "p",
      { id: helpId, class: "help" },
      field.help ? el("span", { class: "help-text" }, field.help) : null,
      el("span", { class: "help-rules" }, rules ? `${rules} · ` : "", `worked example: ${shownText(field, seedText)}`),
    );
    const error = el("p", { id: errId, class: "field-error", hidden: true });
    const keyTag = el("code", { class: "field-key", title: "name in the URL" }, key);
    const unit = field.unit ? el("span", { class: "unit" }, ` (${field.unit})`) : null;

    let control;
    let extra = null;
    let getText;
    let setText;
    let label;
    if (field.kind === "flag") {
      control = el("input", { id: inputId, name: key, type: "checkbox", "aria-describedby": helpId });
      let raw = null; // a URL text that is neither "true" nor "false", kept until edited
      getText = () => raw ?? (control.checked ? "true" : "false");
      setText = (t) => {
        const s = String(t).trim().toLowerCase();
        raw = s === "true" || s === "false" ? null : String(t);
        control.checked = s === "true";
      };
      control.addEventListener("input", () => {
        raw = null;
      });
      label = el("label", { for: inputId, class: "flag-label" }, control, " ", field.label, unit, " ", keyTag);
    } else if (field.kind === "choice") {
      control = el("select", { id: inputId, name: key, "aria-describedby": helpId });
      for (const opt of field.options ?? []) {
        control.append(el("option", { value: opt.value }, opt.label ?? opt.value));
      }
      // the chosen option's full text, where a browser cuts it in the box (style.css wraps it where it can)
      const titled = () => {
        control.title = control.selectedOptions[0]?.textContent ?? "";
      };
      getText = () => control.value;
      setText = (t) => {
        const s = String(t);
        for (const o of control.querySelectorAll("option[data-invalid]")) o.remove();
        if (![...control.options].some((o) => o.value === s)) {
          // keep the unknown text so the core can say what is wrong with it
          const bad = el("option", { value: s, "data-invalid": "true" }, `(not an option: ${s})`);
          control.prepend(bad);
        }
        control.value = s;
        titled();
      };
      control.addEventListener("input", () => {
        for (const o of control.querySelectorAll("option[data-invalid]")) {
          if (o.value !== control.value) o.remove();
        }
        titled();
      });
      label = el("label", { for: inputId }, field.label, unit, " ", keyTag);
    } else if (field.kind === "vector" || field.kind === "matrix" || field.kind === "points") {
      control = el("textarea", {
        id: inputId,
        name: key,
        rows: textareaRows(field, seedText),
        spellcheck: "false",
        autocomplete: "off",
        "aria-describedby": helpId,
      });
      getText = () => control.value;
      setText = (t) => {
        control.value = String(t);
        control.rows = textareaRows(field, control.value);
      };
      label = el("label", { for: inputId }, field.label, unit, " ", keyTag);
      if (field.kind === "points" && Array.isArray(field.columns) && field.columns.length) {
        const table = pointsTable(field, key, () => control.value, (text) => {
          control.value = text;
          control.rows = textareaRows(field, text);
          onInput(key);
        });
        const textSet = setText;
        setText = (t) => {
          textSet(t);
          table.refresh();
        };
        control.addEventListener("input", () => table.refresh());
        table.refresh();
        extra = table.element;
      }
    } else {
      // number, integer, and any kind this page does not know yet: a text box
      const negativeAllowed = field.min == null || field.min < 0;
      control = el("input", {
        id: inputId,
        name: key,
        type: "text",
        // phone keypads for "decimal"/"numeric" lack a minus key
        inputmode: negativeAllowed ? null : field.kind === "integer" ? "numeric" : "decimal",
        autocomplete: "off",
        spellcheck: "false",
        "aria-describedby": helpId,
      });
      getText = () => control.value;
      setText = (t) => {
        control.value = String(t);
      };
      label = el("label", { for: inputId }, field.label, unit, " ", keyTag);
    }
    control.addEventListener("input", () => onInput(key));
    if (field.kind === "flag" || field.kind === "choice") {
      // older browsers fire only "change" for these
      control.addEventListener("change", () => onInput(key));
    }

    const wrapper = el("div", { class: `field field-${field.kind}`, "data-key": key }, label, extra, field.kind === "flag" ? null : control, error, help);
    form.append(wrapper);
    controls.set(key, { field, control, error, helpId, errId, getText, setText, seedText, wrapper });
  }

  /** Hides the fields that do not apply to the mode chosen (a field's `when`). */
  const applyWhen = () => {
    for (const [, c] of controls) {
      const when = c.field.when;
      if (!when || !controls.has(when.key)) continue;
      const applies = (when.values ?? []).map(String).includes(controls.get(when.key).getText());
      c.wrapper.hidden = !applies;
      c.control.disabled = !applies;
    }
  };
  form.addEventListener("input", applyWhen);
  form.addEventListener("change", applyWhen);

  return {
    element: form,
    keys: () => [...controls.keys()],
    has: (key) => controls.has(key),
    /** All texts in field order, as [key, text] pairs. */
    entries: () => [...controls].map(([key, c]) => [key, c.getText()]),
    texts: () => Object.fromEntries([...controls].map(([key, c]) => [key, c.getText()])),
    /** Sets only the fields named in `texts` (keys the form lacks are ignored). */
    set(texts) {
      for (const [key, t] of Object.entries(texts || {})) if (controls.has(key)) controls.get(key).setText(t);
      applyWhen();
    },
    /** Sets every field: from `texts` where given, else the seed's value. */
    setAll(texts) {
      for (const [key, c] of controls) c.setText(Object.hasOwn(texts, key) ? texts[key] : c.seedText);
      applyWhen();
    },
    /**
     * Shows each error beside its field; returns the errors for keys the form
     * does not have (to be shown in the general error box).
     */
    showErrors(errors) {
      const rest = {};
      for (const [key, message] of Object.entries(errors || {})) {
        if (!controls.has(key)) rest[key] = message;
      }
      for (const [key, c] of controls) {
        let message = errors && Object.hasOwn(errors, key) ? String(errors[key]) : null;
        // "dpi: must be …" beside the dpi field reads better without the repeated name
        if (message && message.startsWith(`${key}: `)) message = message.slice(key.length + 2);
        // unchanged fields are left alone: a write to each field on every keystroke would
        // recalculate their style in the figure's frame (app.js inputChanged)
        if ((c.shown ?? null) === message) continue;
        c.shown = message;
        if (message) {
          c.error.textContent = message;
          c.error.hidden = false;
          c.control.setAttribute("aria-invalid", "true");
          c.control.setAttribute("aria-describedby", `${c.errId} ${c.helpId}`);
          c.wrapper.classList.add("invalid");
        } else {
          c.error.textContent = "";
          c.error.hidden = true;
          c.control.removeAttribute("aria-invalid");
          c.control.setAttribute("aria-describedby", c.helpId);
          c.wrapper.classList.remove("invalid");
        }
      }
      return rest;
    },
  };
}

/** A field's text as a student reads it: a choice by its label, a flag as on/off, rows by ";". */
function shownText(field, text) {
  if (field.kind === "choice") {
    const opt = (field.options ?? []).find((o) => String(o.value) === String(text));
    if (opt) return opt.label ?? String(opt.value);
  }
  if (field.kind === "flag") return text === "true" ? "on" : "off";
  return String(text).replace(/\n/g, "; ");
}

/**
 * The rows of a point-list text for the table's cells: lines (or ";"-separated
 * parts) of tokens split by spaces or commas, except that in a row whose numbers
 * are separated by spaces only, a comma between two digits is a decimal comma
 * ("0,5 1,5"): the split of the core's one reader (src/practice/read.rs,
 * read_list), which reads the numbers; this only cuts the text into cells.
 */
function splitPoints(text) {
  return String(text)
    .split(/[\n;]/)
    .map((line) => line.trim())
    .filter((line) => line.length > 0)
    .map((line) => {
      const decimalComma = /\s/.test(line) && /\d,\d/.test(line) && !/,(?!\d)|(?<!\d),/.test(line);
      return line.split(decimalComma ? /\s+/ : /[\s,]+/).filter((t) => t.length > 0);
    });
}

/**
 * A table editing a point-list field cell by cell, kept in step with its
 * text (which stays the value the core parses, and the URL's): edits in the
 * table rewrite the text; a new text (typed, pasted, from the URL) rebuilds
 * the table. Rows: one input per column, a remove button; below, "Add point".
 */
function pointsTable(field, key, currentText, onEdit) {
  const cols = field.columns;
  const body = el("tbody");
  const head = el("thead", {}, el("tr", {}, el("th", { scope: "col" }, "#"), ...cols.map((c) => el("th", { scope: "col" }, c)), el("th", { scope: "col" }, el("span", { class: "visually-hidden" }, "Remove"))));
  const table = el("table", { class: "points-table" }, head, body);
  const add = el("button", { type: "button", class: "points-add" }, "+ Add point");
  const element = el("div", { class: "points-editor" }, el("div", { class: "points-scroll" }, table), add);

  const write = () => {
    const lines = [...body.rows]
      .map((tr) => [...tr.querySelectorAll("input")].map((i) => i.value.trim()))
      .filter((cells) => cells.some((c) => c.length > 0))
      // an unfinished row keeps the numbers it has: the core then says how many are missing
      .map((cells) => cells.filter((c) => c.length > 0).join(" "));
    onEdit(lines.join("\n"));
  };
  const renumber = () => {
    [...body.rows].forEach((tr, i) => {
      tr.cells[0].textContent = String(i + 1);
      tr.querySelectorAll("input").forEach((input, j) => input.setAttribute("aria-label", `Point ${i + 1}, ${cols[j]}`));
      tr.querySelector("button").setAttribute("aria-label", `Remove point ${i + 1}`);
    });
  };
  const row = (cells) => {
    const inputs = cols.map((_, j) =>
      el("input", { type: "text", inputmode: "decimal", autocomplete: "off", spellcheck: "false", value: cells[j] ?? "", "data-col": String(j) }),
    );
    for (const input of inputs) input.addEventListener("input", write);
    const remove = el("button", { type: "button", class: "points-remove", title: "Remove this point" }, "×");
    const tr = el("tr", {}, el("th", { scope: "row" }), ...inputs.map((i) => el("td", {}, i)), el("td", {}, remove));
    remove.addEventListener("click", () => {
      const next = tr.nextElementSibling ?? tr.previousElementSibling;
      tr.remove();
      renumber();
      write();
      (next?.querySelector("input") ?? add).focus();
    });
    return tr;
  };
  add.addEventListener("click", () => {
    if (field.max_len != null && body.rows.length >= field.max_len) return;
    const tr = row([]);
    body.append(tr);
    renumber();
    tr.querySelector("input").focus();
  });
  return {
    element,
    /** Rebuilds the rows from the current text (a row with the wrong count of numbers shows what it has). */
    refresh() {
      body.replaceChildren(...splitPoints(currentText()).map((cells) => row(cells)));
      renumber();
    },
  };
}
