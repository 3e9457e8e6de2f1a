// Tiny DOM helpers: the overview builds its views from plain elements, no framework.

/** Creates an element; attrs are properties (on*, className, …) or, for data-/aria- names, attributes. */
export function el(tag, attrs = {}, ...children) {
  const element = document.createElement(tag);
  for (const [key, value] of Object.entries(attrs)) {
    if (value === undefined || value === null) continue;
    if (key.startsWith('data-') || key.startsWith('aria-') || key === 'role' || key === 'for') {
      element.setAttribute(key, value);
    } else {
      element[key] = value;
    }
  }
  append(element, children);
  return element;
}

function append(element, children) {
  for (const child of children.flat(Infinity)) {
    if (child === undefined || child === null || child === false) continue;
    element.append(child instanceof Node ? child : String(child));
  }
}

/**
 * Calls onRow with the value of attribute on the row the operator presses in tbody. One listener on the body, on
 * pointerdown: rows are rebuilt several times a second, so a row's own click handler would often be lost between
 * the press and the release.
 */
export function onRowPress(tbody, attribute, onRow) {
  tbody.addEventListener('pointerdown', (event) => {
    if (event.button !== 0) return;
    const row = event.target.closest(`tr[${attribute}]`);
    if (row && tbody.contains(row)) onRow(row.getAttribute(attribute));
  });
}

/** Replaces the element's content. */
export function fill(element, ...children) {
  element.replaceChildren();
  append(element, children);
  return element;
}

/** A two-column table of name/value rows. */
export function propertyTable(rows) {
  return el('table', { className: 'props' },
    rows.map(([name, value]) => el('tr', {}, el('th', {}, name), el('td', {}, value ?? '—'))));
}

/** An openTCS timestamp as a local time, or "—" for none (openTCS writes the far future for "never"). */
export function formatTime(iso) {
  if (!iso) return '—';
  const time = Date.parse(iso);
  if (!Number.isFinite(time) || new Date(time).getUTCFullYear() > 9000) return '—';
  return new Date(time).toLocaleString();
}

/** A duration in milliseconds as "1h 02m", "3m 05s" or "12s". */
export function formatDuration(ms) {
  const seconds = Math.max(0, Math.round(ms / 1000));
  const h = Math.floor(seconds / 3600);
  const m = Math.floor((seconds % 3600) / 60);
  const s = seconds % 60;
  if (h > 0) return `${h}h ${String(m).padStart(2, '0')}m`;
  if (m > 0) return `${m}m ${String(s).padStart(2, '0')}s`;
  return `${s}s`;
}
