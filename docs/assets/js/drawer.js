// The theme's navigation drawer (below 76.25em the site's menu slides in from the
// side): while it is closed it sits off-screen, so it leaves the tab order and the
// accessibility tree (inert) and comes back the moment it opens. Wider, the same
// element is the visible left-hand menu and stays as it is. The search's results
// box is a tab stop of its own even while closed and empty (an invisible stop
// after the search field): it is one only while it holds results.

const NARROW = "(max-width: 76.2344em)"; // the theme's breakpoint: the menu is a drawer below 76.25em

let media = null;

/** Make the closed drawer inert, the open (or wide) menu not. */
export function updateDrawer() {
  const toggle = /** @type {HTMLInputElement | null} */ (document.querySelector('input[data-md-toggle="drawer"]'));
  const closed = Boolean(media?.matches) && !toggle?.checked;
  for (const el of /** @type {NodeListOf<HTMLElement>} */ (document.querySelectorAll(".md-sidebar--primary"))) {
    el.inert = closed;
  }
  searchStop();
}

/** The search's results box is a tab stop only while it holds results (hidden while closed: workbook.css). */
function searchStop() {
  const box = /** @type {HTMLElement | null} */ (document.querySelector(".md-search__scrollwrap"));
  const list = box?.querySelector(".md-search-result__list");
  if (box) box.tabIndex = list?.children.length ? 0 : -1;
}

export function initDrawer() {
  if (media) return updateDrawer();
  media = matchMedia(NARROW);
  media.addEventListener("change", updateDrawer);
  // The drawer's checkbox changes by its labels (menu button, overlay) and, from other code, by click().
  document.addEventListener("change", (event) => {
    if (/** @type {Element | null} */ (event.target)?.matches?.('input[data-md-toggle="drawer"]')) updateDrawer();
  });
  const results = document.querySelector(".md-search-result__list");
  if (results) new MutationObserver(searchStop).observe(results, { childList: true });
  updateDrawer();
}
