// One renderer for every checker's result: state attribute, message, test rows.

const STATE_FOR = { correct: "correct", incorrect: "incorrect", invalid: "invalid", error: "error" };

export function setPending(el) {
  el.dataset.state = "pending";
  el.setAttribute("aria-busy", "true");
}

export function showResult(el, result) {
  el.removeAttribute("aria-busy");
  el.dataset.state = STATE_FOR[result.status] || "error";
  if (result.tag) el.dataset.feedback = result.tag;
  else delete el.dataset.feedback;
  const box = el.querySelector('[data-role="feedback"]');
  box.replaceChildren();
  const lead = result.tag === "timeout" ? "" : { correct: "Correct.", incorrect: "Not yet.", invalid: "", error: "Something went wrong." }[result.status] ?? "";
  const p = document.createElement("p");
  const message = result.message || "";
  if (lead && !message.startsWith(lead.replace(".", ""))) {
    const strong = document.createElement("strong");
    strong.textContent = lead + " ";
    p.append(strong);
  }
  p.append(message);
  box.append(p);
}

export function showMessage(el, text) {
  const box = el.querySelector('[data-role="feedback"]');
  const p = document.createElement("p");
  p.textContent = text;
  box.replaceChildren(p);
}

export function renderTests(el, result) {
  const panel = el.querySelector('[data-role="tests"]');
  const out = el.querySelector('[data-role="stdout"]');
  const data = result.data || {};
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
    table.innerHTML = "<thead><tr><th scope=col>Test</th><th scope=col>Expected</th><th scope=col>Got</th><th scope=col>Result</th></tr></thead>";
    const body = document.createElement("tbody");
    for (const row of rows) {
      const tr = document.createElement("tr");
      tr.dataset.role = "test-result";
      tr.dataset.passed = String(Boolean(row.passed));
      const cells = [row.input, row.expected, row.actual, row.passed ? "✓ pass" : "✗ fail"];
      for (const text of cells) {
        const td = document.createElement("td");
        const code = document.createElement("code");
        code.textContent = text ?? "";
        td.append(code);
        tr.append(td);
      }
      tr.lastChild.replaceChildren(row.passed ? "✓ pass" : "✗ fail");
      body.append(tr);
      if (!row.passed && row.message && row.message !== "values differ") {
        const note = document.createElement("tr");
        note.className = "wb-test-note";
        const td = document.createElement("td");
        td.colSpan = 4;
        const pre = document.createElement("pre");
        pre.textContent = row.message;
        td.append(pre);
        note.append(td);
        body.append(note);
      }
    }
    table.append(body);
    panel.append(table);
  }
  out.hidden = !data.stdout;
  out.textContent = data.stdout ? `Printed output:\n${data.stdout}` : "";
}
