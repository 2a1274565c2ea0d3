// Says when the site's search is wanted, so that its worker builds the index then
// (search-worker.js): when the learner opens the search (its toggle, a shortcut, or focus in its
// box), or once the page has been idle a while after the grader is ready, so that the index is
// usually built before anyone asks for it. Listeners sit on the document: the theme's instant
// navigation keeps the search and its worker, and so does this.

import { SEARCH_ASKS, SEARCH_CHANNEL, SEARCH_WANTED } from "./search-channel.js";
import { delay, idle, runtimeSettled } from "./wait.js";

const AFTER_READY_MS = 5_000;
const SEARCH = "[data-md-component=search]"; // the theme's search (its box and its results)
const TOGGLE = "[data-md-toggle=search]"; // the theme's checkbox that opens it

let channel = null;
let wanted = false;

function want() {
  if (wanted || !channel) return;
  wanted = true;
  channel.postMessage(SEARCH_WANTED);
}

export function initSearchStart() {
  if (channel || typeof BroadcastChannel === "undefined") return; // the worker builds at once then
  channel = new BroadcastChannel(SEARCH_CHANNEL);
  channel.onmessage = (event) => {
    if (event.data === SEARCH_ASKS && wanted) channel.postMessage(SEARCH_WANTED);
  };
  document.addEventListener("focusin", (event) => {
    if (event.target instanceof Element && event.target.closest(SEARCH)) want();
  });
  document.addEventListener("change", (event) => {
    if (event.target instanceof Element && event.target.matches(TOGGLE)) want();
  });
  runtimeSettled()
    .then(() => delay(AFTER_READY_MS))
    .then(() => idle(5_000))
    .then(want);
}
