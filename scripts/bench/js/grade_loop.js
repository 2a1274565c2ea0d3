// Checks an exercise `n` times; each time from the click to the data-state change.
async ({ id, n, timeoutMs, C }) => {
  const B = window.__bench;
  const el = B.exercise(id);
  if (!el) throw new Error(`no exercise ${id} on this page`);
  const button = el.querySelector(C.sel.check);
  const times = [], states = [];
  for (let i = 0; i < n; i++) {
    const { ms, state } = await B.clickAndWait(el, button, timeoutMs);
    times.push(ms); states.push(state);
    await new Promise((r) => setTimeout(r, 5));
  }
  return { times, states };
}
