// The installed app (docs/hooks/app.py writes its manifest): its start URL, the site root with
// ?source=app, opens the last page read, which every page remembers in local storage (one key
// per site root). The 404 page (the one page with a <base>: docs/overrides/main.html) is never
// remembered.
const SOURCE = "app";

const keyFor = (siteRoot) => `robotics-workbook:${new URL(siteRoot).pathname}:last-page`;

function read(key) {
  try {
    return localStorage.getItem(key);
  } catch {
    return null; // storage refused: the app opens on its home page
  }
}

/** At the start URL: go on to the last page read (true: leaving), else drop the marker from the address. */
export function openLastPage(siteRoot, here = new URL(location.href)) {
  if (here.searchParams.get("source") !== SOURCE) return false;
  const last = read(keyFor(siteRoot));
  const target = last && new URL(last, siteRoot);
  here.searchParams.delete("source");
  if (target && target.href.startsWith(siteRoot) && target.href !== here.href) {
    location.replace(target.href);
    return true;
  }
  history.replaceState(history.state, "", here.href);
  return false;
}

/** Remember the page on screen (called on every page, instant navigation included). */
export function rememberPage(siteRoot, here = new URL(location.href)) {
  if (!here.href.startsWith(siteRoot) || document.head.querySelector("base")) return;
  here.searchParams.delete("source");
  try {
    localStorage.setItem(keyFor(siteRoot),
      here.pathname.slice(new URL(siteRoot).pathname.length) + here.search || "./");
  } catch {
    /* storage refused: nothing to remember with */
  }
}

export function initApp(siteRoot) {
  if (openLastPage(siteRoot)) return;
  rememberPage(siteRoot);
  window.document$?.subscribe?.(() => rememberPage(siteRoot));
}
