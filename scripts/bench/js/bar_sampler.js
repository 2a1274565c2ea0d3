// Every 250 ms, what the first loading message on the page shows (loading.js): [time, bar value, bar max,
// text, phase]; the bench reads window.__benchBar. Installed as an init script, before the page's scripts.
(C) => {
  const samples = window.__benchBar = [];
  setInterval(() => {
    const box = document.querySelector(C.sel["runtime-status"]);
    if (!box) return;
    const bar = box.querySelector(C.sel["runtime-progress"]);
    samples.push([performance.now(), bar ? bar.value : null, bar ? bar.max : null, box.textContent,
      box.getAttribute(C.attr.phase)]);
  }, 250);
}
