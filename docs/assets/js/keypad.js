// The keypad row of a touch screen (issue 48): while an answer input with data-keys has the
// focus, a row of the symbols its answer may need (the answer kind lists them: markup.keypad)
// sits above the on-screen keyboard, so a learner never goes to the keyboard's symbol pages.
// A key inserts its symbol at the caret and never takes the focus (its pointerdown is
// cancelled, so the keyboard stays up); the row's live region says what went in.
import { ATTR, ROLE } from "./contract.js";

const NAMES = {
  "−": "minus", "+": "plus", "×": "times", "/": "divided by", "^": "to the power", "(": "opening parenthesis",
  ")": "closing parenthesis", "√": "square root", "π": "pi", "°": "degrees", "θ": "theta",
};

let row = null;
let said = null;
let target = null;

/** What a key inserts before the caret: a unit (a word or m/s) is set off by a space. */
export function insertion(key, before) {
  const unit = key.length > 1 || /^[a-z]$/i.test(key);
  return unit && before && !/\s$/.test(before) ? ` ${key}` : key;
}

function insert(key) {
  const input = target;
  if (!input?.isConnected) return;
  const [from, to] = [input.selectionStart ?? input.value.length, input.selectionEnd ?? input.value.length];
  input.setRangeText(insertion(key, input.value.slice(0, from)), from, to, "end");
  input.dispatchEvent(new Event("input", { bubbles: true }));
  said.textContent = "";
  said.textContent = `${NAMES[key] || key} inserted`;
}

function build() {
  row = document.createElement("div");
  row.className = "wb-keypad";
  row.setAttribute(ATTR.role, ROLE.keypad);
  row.setAttribute("role", "toolbar");
  row.setAttribute("aria-label", "Symbols for the answer");
  row.hidden = true;
  said = document.createElement("span");
  said.className = "wb-sr-only";
  said.setAttribute("aria-live", "polite");
  row.append(said);
  // Keep the focus (and the keyboard) in the answer: no key ever takes it.
  row.addEventListener("pointerdown", (event) => event.preventDefault());
  row.addEventListener("mousedown", (event) => event.preventDefault());
  row.addEventListener("click", (event) => {
    const key = event.target.closest?.("button")?.dataset.key;
    if (key) insert(key);
  });
  window.visualViewport?.addEventListener("resize", place);
  window.visualViewport?.addEventListener("scroll", place);
}

function keys(list) {
  const buttons = list.map((key) => {
    const b = document.createElement("button");
    b.type = "button";
    b.tabIndex = -1;
    b.className = "wb-keypad-key";
    b.setAttribute(ATTR.role, ROLE.keypadKey);
    b.dataset.key = key;
    b.textContent = key;
    if (NAMES[key]) b.setAttribute("aria-label", NAMES[key]);
    return b;
  });
  row.replaceChildren(said, ...buttons);
}

// Just above the on-screen keyboard: the part of the layout viewport the visual one leaves below it.
function place() {
  if (!row || row.hidden) return;
  const view = window.visualViewport;
  const below = view ? Math.max(0, window.innerHeight - view.height - view.offsetTop) : 0;
  row.style.bottom = `${below}px`;
}

function show(input) {
  if (!row) build();
  if (!row.isConnected) document.body.append(row); // instant navigation replaces the body's content
  target = input;
  const list = input.getAttribute(ATTR.keys).split(" ").filter(Boolean);
  if (row.dataset.keys !== list.join(" ")) {
    keys(list);
    row.dataset.keys = list.join(" ");
  }
  row.hidden = false;
  document.documentElement.classList.add("wb-keypad-open");
  place();
  input.scrollIntoView({ block: "nearest" });
}

function hide() {
  target = null;
  if (row) row.hidden = true;
  document.documentElement.classList.remove("wb-keypad-open");
}

const keyed = (el) => el instanceof HTMLInputElement && el.hasAttribute(ATTR.keys);

/** On a touch screen: show the row for every answer input that gets the focus, on every page. */
export function initKeypad() {
  document.addEventListener("focusin", (event) => {
    if (keyed(event.target)) show(event.target);
    else hide();
  });
  document.addEventListener("focusout", (event) => {
    if (event.target === target && !keyed(event.relatedTarget)) hide();
  });
  if (keyed(document.activeElement)) show(document.activeElement);
}

