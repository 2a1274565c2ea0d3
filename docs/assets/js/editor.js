// The Build exercises' code editor: CodeMirror 6 with Python, 4-space indents,
// Ctrl/Cmd-Enter to run, colours taken from the Material palette (light/dark).
// Tab indents once the learner works in the editor (has typed, pressed Enter or
// clicked in it since the focus came in): a keyboard user passing through moves on
// and the code stays as it was. The way out (Escape, then Tab) is written under the
// editor, for everyone to see, and the editor draws a focus ring (workbook.css).
// Lines never wrap (Python's columns matter): on a phone the editor takes the
// screen's whole width (workbook.css) and a longer line scrolls.

import { indentLess, indentMore } from "@codemirror/commands";
import { python } from "@codemirror/lang-python";
import { HighlightStyle, indentUnit, syntaxHighlighting } from "@codemirror/language";
import { EditorState, StateEffect, StateField } from "@codemirror/state";
import { Decoration, EditorView, keymap } from "@codemirror/view";
import { tags as t } from "@lezer/highlight";
import { basicSetup } from "codemirror";

/** @type {import("@codemirror/state").StateEffectType<number | null>} */
const setErrorLine = StateEffect.define();
const errorLine = StateField.define({
  create: () => Decoration.none,
  update(deco, tr) {
    deco = deco.map(tr.changes);
    for (const effect of tr.effects) {
      if (effect.is(setErrorLine)) {
        const number = effect.value;
        if (number == null || number > tr.state.doc.lines) return Decoration.none;
        const line = tr.state.doc.line(number);
        deco = Decoration.set([Decoration.line({ class: "wb-error-line" }).range(line.from)]);
      }
    }
    return tr.docChanged ? Decoration.none : deco;
  },
  provide: (field) => EditorView.decorations.from(field),
});

const paletteTheme = EditorView.theme({
  "&": { color: "var(--md-code-fg-color)", backgroundColor: "var(--md-code-bg-color)", fontSize: ".8rem" },
  ".cm-content": { fontFamily: "var(--md-code-font-family, monospace)", caretColor: "var(--md-typeset-color)" },
  ".cm-gutters": {
    backgroundColor: "var(--md-code-bg-color)", color: "var(--md-default-fg-color--light)", border: "none" },
  // The current line is marked in the gutter only: a tinted line lowers the text's contrast.
  ".cm-activeLine": { backgroundColor: "transparent" },
  ".cm-activeLineGutter": {
    backgroundColor: "var(--md-default-fg-color--lightest)", color: "var(--md-default-fg-color)" },
  "&.cm-focused .cm-cursor": { borderLeftColor: "var(--md-typeset-color)" },
  ".cm-selectionBackground, &.cm-focused .cm-selectionBackground": {
    backgroundColor: "var(--md-accent-fg-color--transparent) !important" },
});

// Syntax colours from the palette's own code colours (readable in light and dark).
const paletteHighlight = HighlightStyle.define([
  { tag: [t.keyword, t.controlKeyword, t.definitionKeyword, t.moduleKeyword, t.operatorKeyword, t.self],
    color: "var(--md-code-hl-keyword-color)" },
  { tag: [t.string, t.special(t.string)], color: "var(--md-code-hl-string-color)" },
  { tag: [t.number, t.bool, t.null], color: "var(--md-code-hl-number-color)" },
  { tag: t.comment, color: "var(--md-code-hl-comment-color)", fontStyle: "italic" },
  { tag: [t.function(t.variableName), t.function(t.propertyName), t.function(t.definition(t.variableName))],
    color: "var(--md-code-hl-function-color)" },
  { tag: [t.className, t.definition(t.className)], color: "var(--md-code-hl-name-color)" },
  { tag: [t.operator, t.punctuation, t.bracket], color: "var(--md-code-hl-punctuation-color)" },
  { tag: t.invalid, color: "var(--md-code-hl-special-color)" },
]);

let hints = 0;
const HINT = "Tab indents once you type here. To leave the editor, press Esc, then Tab. "
  + "Ctrl+Enter (⌘+Enter on a Mac) runs the tests.";

export function createEditor(host, doc, { onChange, onRun }) {
  // Whether this visit of the focus works in the editor: until then, Tab moves on.
  let working = false;
  const tab = (command) => (view) => (working ? command(view) : false);
  const hint = Object.assign(document.createElement("p"),
    { className: "wb-editor-hint", id: `wb-editor-hint-${++hints}`, textContent: HINT });
  const view = new EditorView({
    parent: host,
    state: EditorState.create({
      doc,
      extensions: [
        keymap.of([
          { key: "Mod-Enter", run: () => (onRun(), true) },
          { key: "Tab", run: tab(indentMore), shift: tab(indentLess) },
          { key: "Escape", run: () => ((working = false), false) },
        ]),
        EditorView.domEventHandlers({
          blur: () => { working = false; },
          mousedown: () => { working = true; },
          keydown: (event) => {
            const typing = event.key.length === 1 && !event.ctrlKey && !event.metaKey && !event.altKey;
            if (event.key === "Enter" || typing) working = true;
          },
        }),
        syntaxHighlighting(paletteHighlight),
        basicSetup,
        python(),
        indentUnit.of("    "),
        EditorState.tabSize.of(4),
        paletteTheme,
        errorLine,
        EditorView.contentAttributes.of(
          { "aria-label": "Python code editor", "aria-describedby": hint.id, tabindex: "0" }),
        EditorView.updateListener.of((update) => {
          if (update.transactions.some((tr) => tr.isUserEvent("input") || tr.isUserEvent("delete"))) working = true;
          if (update.docChanged) onChange(update.state.doc.toString());
        }),
      ],
    }),
  });
  host.append(hint);
  return {
    view,
    getCode: () => view.state.doc.toString(),
    setCode(code) {
      view.dispatch({ changes: { from: 0, to: view.state.doc.length, insert: code } });
    },
    markLine(line) {
      // Clearing a mark that is not there changes nothing: no update (and no layout it would force).
      if (line == null && view.state.field(errorLine).size === 0) return;
      view.dispatch({ effects: setErrorLine.of(line) });
    },
  };
}
