// How the page and the search worker that stands in for the theme's (search-worker.js) talk:
// a BroadcastChannel of the site's origin. The worker asks when it starts; the page says when
// search is wanted (search-start.js), and says it again to a worker that asks later.
export const SEARCH_CHANNEL = "robotics-workbook:search";
export const SEARCH_ASKS = "asks";
export const SEARCH_WANTED = "wanted";
