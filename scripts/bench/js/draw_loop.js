// Draws new numbers `n` times on each of `ids`; each time from the click on "New
// numbers" to data-variant changing, which the page sets last, once the
// statement, hint and label are replaced and typeset (the worker's draw, the DOM
// and KaTeX all inside).
async ({ ids, n, timeoutMs, C }) => {
  const B = window.__bench;
  const times = [];
  for (let i = 0; i < n; i++) {
    for (const id of ids) {
      const el = B.exercise(id);
      if (!el) throw new Error(`no exercise ${id} on this page`);
      const button = el.querySelector(C.sel["new-variant"]);
      const before = el.getAttribute(C.attr.variant);
      let mo, timer;
      const done = new Promise((resolve, reject) => {
        mo = new MutationObserver(() => {
          if (el.getAttribute(C.attr.variant) !== before) resolve(performance.now());
        });
        mo.observe(el, { attributes: true, attributeFilter: [C.attr.variant] });
        timer = setTimeout(() => reject(new Error(`exercise ${id}: no new variant within ${timeoutMs} ms`)), timeoutMs);
      });
      const t0 = performance.now();
      button.click();
      try {
        times.push((await done) - t0);
      } finally {
        mo.disconnect();
        clearTimeout(timer);
      }
      await new Promise((r) => setTimeout(r, 5));
    }
  }
  return { times };
}
