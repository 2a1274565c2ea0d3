// Page-level notices at the top of the content: what the learner must know about
// their saved progress (storage full, a record that could not be read) or about
// the page's address (a link to numbers that do not exist). Each notice has a
// key, so it is shown once and can be taken back; progress notices come with the
// buttons that keep the learner's work: export everything, download what could
// not be read.

/** Save `text` as a file called `name` (the browser's download). */
export function download(name, text, type = "application/json") {
  const url = URL.createObjectURL(new Blob([text], { type }));
  const a = Object.assign(document.createElement("a"), { href: url, download: name });
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10_000);
}

/** Show (or update) notice `key`: a title, a sentence and optional buttons [{text, action, run}]. */
export function showNotice(key, title, text, buttons = []) {
  const main = document.querySelector(".md-content__inner");
  if (!main) return null;
  let box = /** @type {HTMLElement | null} */ (main.querySelector(`[data-wb-notice="${key}"]`));
  if (!box) {
    box = document.createElement("div");
    box.className = "admonition warning wb-notice";
    box.setAttribute("role", "alert");
    box.dataset.wbNotice = key;
    main.prepend(box);
  }
  const head = Object.assign(document.createElement("p"), { className: "admonition-title", textContent: title });
  const body = Object.assign(document.createElement("p"), { textContent: text });
  box.replaceChildren(head, body);
  if (buttons.length) {
    const row = Object.assign(document.createElement("p"), { className: "wb-notice-actions" });
    for (const { text: label, action, run } of buttons) {
      const b = Object.assign(document.createElement("button"), { type: "button", className: "md-button",
        textContent: label });
      b.dataset.wbAction = action;
      b.addEventListener("click", run);
      row.append(b);
    }
    box.append(row);
  }
  return box;
}

export function clearNotice(key) {
  document.querySelector(`[data-wb-notice="${key}"]`)?.remove();
}

/** The export file of `progress`, downloaded. */
export function exportProgress(progress) {
  const data = progress.exportData();
  const name = `robotics-math-workbook-progress-${data.exported.slice(0, 10)}.json`;
  download(name, JSON.stringify(data, null, 1));
  return { name, count: Object.keys(data.exercises).length };
}

/**
 * Every problem the progress store reported, as notices with their way out: on
 * every page while it lasts (storage full, nothing saved), once for what is
 * only news (a record set aside).
 */
export function showProgressProblems(progress) {
  for (const problem of progress.problems) {
    if (problem.shown && problem.kind === "set-aside") continue;
    problem.shown = true;
    /** @type {{ text: string, action: string, run: () => unknown }[]} */
    const buttons = [{ text: "Export progress", action: "notice-export", run: () => exportProgress(progress) }];
    if (problem.download) {
      const { name, text } = problem.download;
      buttons.push({ text: "Download the unreadable copy", action: "notice-download",
        run: () => download(name, text) });
    }
    showNotice(`progress-${problem.kind}`, "Progress", problem.message, buttons);
  }
}
