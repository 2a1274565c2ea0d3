// One renderer for every reply: the exercise's state attribute, its message,
// and a Build run's test rows. The wording comes from the grader (Python); this
// module only places it.

import { ATTR, ROLE, STATE, findRole, ownRole } from "./contract.js";
import { fillMath, renderMath } from "./math.js";

export function setPending(el) {
  el.setAttribute(ATTR.state, STATE.pending);
  el.setAttribute("aria-busy", "true");
}

/** Show a reply envelope: {ok: true, value: verdict} or {ok: false, error: {kind, message}}. */
export function showReply(el, reply) {
  el.removeAttribute("aria-busy");
  const verdict = reply.ok ? reply.value : null;
  el.setAttribute(ATTR.state, verdict ? verdict.status : STATE.error);
  const tag = verdict ? verdict.tag : reply.error.kind;
  if (tag) el.setAttribute(ATTR.tag, tag);
  else el.removeAttribute(ATTR.tag);
  showMessage(el, verdict ? verdict.message : reply.error.message, verdict?.data?.math);
}

/** Where `el`'s messages go: an exercise's own feedback, or a checked step's (work-step-feedback). */
export const feedbackOf = (el) => ownRole(el, ROLE.feedback) ?? ownRole(el, ROLE.workStepFeedback);

/** Show one message; `math` (a verdict's data.math) is the same text with its formulas
 *  marked, which are typeset with KaTeX as the page's own are. */
export function showMessage(el, text, math = null) {
  const p = document.createElement("p");
  if (Array.isArray(math) && math.length) fillMath(p, math);
  else p.textContent = text;
  feedbackOf(el).replaceChildren(p);
  if (Array.isArray(math) && math.length) renderMath(p);
}

// A number in a test's call or value never breaks across lines (a narrow column may break the call
// between its arguments, or inside a long name, but "1.570796" stays whole).
const NUMBER = /-?\d+(?:\.\d+)?(?:e[-+]?\d+)?/gi;

function codeOf(text) {
  const code = document.createElement("code");
  let at = 0;
  for (const m of text.matchAll(NUMBER)) {
    if (m.index > at) code.append(text.slice(at, m.index));
    const num = document.createElement("span");
    num.className = "wb-num";
    num.textContent = m[0];
    code.append(num);
    at = m.index + m[0].length;
  }
  if (at < text.length) code.append(text.slice(at));
  return code;
}

function testRow(row) {
  const tr = document.createElement("tr");
  tr.setAttribute(ATTR.role, ROLE.testResult);
  tr.setAttribute(ATTR.passed, String(Boolean(row.passed)));
  for (const text of [row.input, row.expected, row.actual]) {
    const td = document.createElement("td");
    td.append(codeOf(String(text ?? "")));
    tr.append(td);
  }
  const result = document.createElement("td");
  result.textContent = row.passed ? "✓ pass" : "✗ fail";
  tr.append(result);
  return tr;
}

function noteRow(message) {
  const pre = document.createElement("pre");
  pre.textContent = message;
  const td = document.createElement("td");
  td.colSpan = 4;
  td.append(pre);
  const tr = document.createElement("tr");
  tr.className = "wb-test-note";
  tr.append(td);
  return tr;
}

/** A Build run's rows (and traceback, and printed output) from a reply. */
export function renderTests(el, reply) {
  const panel = findRole(el, ROLE.tests);
  const out = findRole(el, ROLE.stdout);
  const data = (reply.ok && reply.value.data) || {};
  const rows = data.tests || [];
  panel.replaceChildren();
  panel.hidden = rows.length === 0 && !data.error;
  if (data.error && rows.length === 0) {
    const pre = document.createElement("pre");
    pre.className = "wb-traceback";
    pre.textContent = data.error.traceback;
    panel.append(pre);
  }
  if (rows.length) {
    const table = document.createElement("table");
    table.className = "wb-test-table";
    table.innerHTML = "<thead><tr><th scope=col>Test</th><th scope=col>Expected</th><th scope=col>Got</th>"
      + "<th scope=col>Result</th></tr></thead>";
    const body = document.createElement("tbody");
    for (const row of rows) {
      body.append(testRow(row));
      if (!row.passed && row.message) body.append(noteRow(row.message));
    }
    table.append(body);
    panel.append(table);
  }
  out.hidden = !data.stdout;
  out.textContent = data.stdout ? `Printed output:\n${data.stdout}` : "";
}
