// Small DOM helpers the page's modules share.

/** A new element with `props` and `children`. */
export function el(tag, props = {}, ...children) {
  const node = Object.assign(document.createElement(tag), props);
  node.append(...children);
  return node;
}
