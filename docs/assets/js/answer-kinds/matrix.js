// A vector or matrix answer: a grid of entries. Arrow keys move between entries
// (left and right once the caret is at the edge), Tab goes in reading order, so does
// Enter (a phone keyboard's "next") up to the last entry, where it checks (and in an entry
// holding a whole matrix typed, the others empty: it is read so at Check); and a
// whole matrix pasted into any entry is split by the grader and fills the grid; one
// value pasted (even a long expression) stays in the entry it was pasted into. A whole
// matrix typed into one entry, the others empty, is split the same way once the entry
// is left (and the grader reads it so if Check comes first).
import { ATTR, ROLE, TAG, ownRoles } from "../contract.js";
import { showMessage } from "../feedback.js";

export function init(ctx) {
  const entries = ownRoles(ctx.el, ROLE.entry);
  const at = (r, c) => entries.find((e) => Number(e.getAttribute(ATTR.row)) === r
    && Number(e.getAttribute(ATTR.col)) === c);
  const rows = Math.max(...entries.map((e) => Number(e.getAttribute(ATTR.row))));
  const cols = Math.max(...entries.map((e) => Number(e.getAttribute(ATTR.col))));
  const fill = (grid) => {
    grid.forEach((row, i) => row.forEach((text, j) => {
      const input = at(i + 1, j + 1);
      if (input) input.value = text;
    }));
  };
  // A whole matrix typed into one entry, the others empty: read as a paste (on leaving it, or at Check).
  const wholeIn = (input) => entries.length >= 2 && /[\s,;[\]]/.test(input.value.trim())
    && entries.every((e) => e === input || !e.value.trim());
  for (const input of entries) {
    const r = Number(input.getAttribute(ATTR.row));
    const c = Number(input.getAttribute(ATTR.col));
    input.addEventListener("keydown", (event) => {
      const next = c < cols ? at(r, c + 1) : at(r + 1, 1);
      if (event.key === "Enter" && !event.shiftKey && !event.isComposing && next && !wholeIn(input)) {
        event.preventDefault(); // the last entry's Enter (or a whole matrix's) submits: Check
        next.focus();
        next.select();
        return;
      }
      const atStart = input.selectionStart === 0 && input.selectionEnd === 0;
      const atEnd = input.selectionStart === input.value.length;
      const moves = { ArrowUp: [r - 1, c], ArrowDown: [r + 1, c], ArrowLeft: atStart ? [r, c - 1] : null,
        ArrowRight: atEnd ? [r, c + 1] : null };
      const target = moves[event.key] && at(...moves[event.key]);
      if (!target) return;
      event.preventDefault();
      target.focus();
      target.select();
    });
    input.addEventListener("change", async () => {
      // A whole matrix typed (not pasted) into one entry, the others empty: split it as a paste.
      const text = input.value;
      if (!wholeIn(input)) return;
      const reply = await ctx.runtime.request(
        { op: "split", exercise: ctx.id, variant: ctx.variant, step: ctx.step, text });
      if (reply.ok && reply.value.entries && input.value === text) fill(reply.value.entries);
    });
    input.addEventListener("paste", async (event) => {
      const text = event.clipboardData?.getData("text") ?? "";
      if (entries.length < 2 || !/[\s,;[\]]/.test(text.trim())) return; // one value: paste as usual
      event.preventDefault();
      const at = [input.selectionStart ?? input.value.length, input.selectionEnd ?? input.value.length];
      const reply = await ctx.runtime.request(
        { op: "split", exercise: ctx.id, variant: ctx.variant, step: ctx.step, text });
      if (reply.ok && typeof reply.value.cell === "string") {
        input.setRangeText(reply.value.cell, at[0], at[1], "end");
        input.dispatchEvent(new Event("input", { bubbles: true }));
      } else if (reply.ok && reply.value.entries) fill(reply.value.entries);
      else showMessage(ctx.el, reply.ok ? reply.value.message : reply.error.message);
    });
  }
  return {
    value: () => Array.from({ length: rows },
      (_, i) => Array.from({ length: cols }, (_, j) => at(i + 1, j + 1)?.value ?? "")),
    restore(last) {
      // what the learner typed meanwhile stays
      if (Array.isArray(last) && entries.every((input) => !input.value)) fill(last);
    },
    clear() {
      for (const input of entries) {
        input.value = "";
        input.removeAttribute("aria-invalid");
        input.removeAttribute(ATTR.tag);
      }
    },
    show(reply) {
      const data = (reply.ok && reply.value.data) || {};
      const positions = (list) => new Set((list || []).map(([r, c]) => `${r},${c}`));
      const marked = positions([...(data.wrong || []), ...(data.invalid || [])]);
      const close = positions(data.close);
      for (const input of entries) {
        const key = `${input.getAttribute(ATTR.row)},${input.getAttribute(ATTR.col)}`;
        if (marked.has(key)) input.setAttribute("aria-invalid", "true");
        else input.removeAttribute("aria-invalid");
        if (close.has(key)) input.setAttribute(ATTR.tag, TAG.close); // near the key: rounded too far
        else input.removeAttribute(ATTR.tag);
      }
    },
  };
}
