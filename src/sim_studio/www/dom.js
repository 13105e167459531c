// Small DOM helpers any view may import ('/dom.js'): elements built from names, attributes and
// children, text always set as text (names from the ROS graph never become markup).

export function el(tag, attributes = {}, ...children) {
  const node = document.createElement(tag);
  for (const [name, value] of Object.entries(attributes)) {
    if (value !== undefined && value !== null && value !== false) node.setAttribute(name, value === true ? '' : value);
  }
  for (const child of children) {
    if (child !== undefined && child !== null) node.append(child instanceof Node ? child : String(child));
  }
  return node;
}

export function clear(node) {
  while (node.firstChild) node.removeChild(node.firstChild);
  return node;
}

// The same with two shorthands: {class: ...} and {text: ...} (the element's text).
export function element(tag, attributes = {}, ...children) {
  const {text, ...rest} = attributes;
  const node = el(tag, rest, ...children);
  if (text !== undefined) node.textContent = text;
  return node;
}
