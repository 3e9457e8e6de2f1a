// Small SVG charts for the statistics panel: vertical bars and stacked horizontal bars.

const SVG = 'http://www.w3.org/2000/svg';

function node(name, attributes = {}, text) {
  const element = document.createElementNS(SVG, name);
  Object.entries(attributes).forEach(([key, value]) => element.setAttribute(key, value));
  if (text !== undefined) element.textContent = text;
  return element;
}

/** Vertical bars: values [{label, value, title?}], the tallest bar is full height. */
export function barChart(values, { width = 420, height = 120, colour = '#1565c0', unit = '' } = {}) {
  const svg = node('svg', { width, height: height + 30, viewBox: `0 0 ${width} ${height + 30}`, role: 'img' });
  const max = Math.max(1, ...values.map((v) => v.value));
  const slot = width / Math.max(1, values.length);
  values.forEach((v, i) => {
    const barHeight = (v.value / max) * height;
    const bar = node('rect', { x: i * slot + 2, y: height - barHeight + 12, width: Math.max(1, slot - 4), height: barHeight, fill: colour });
    bar.append(node('title', {}, `${v.title ?? v.label}: ${v.value}${unit}`));
    svg.append(bar);
    if (v.value > 0) svg.append(node('text', { x: i * slot + slot / 2, y: height - barHeight + 10, 'text-anchor': 'middle', 'font-size': 10 }, String(v.value)));
    if (values.length <= 20 || i % Math.ceil(values.length / 10) === 0) {
      svg.append(node('text', { x: i * slot + slot / 2, y: height + 26, 'text-anchor': 'middle', 'font-size': 10, fill: '#555' }, v.label));
    }
  });
  return svg;
}

/** One horizontal bar per row, split into the parts' shares: rows [{label, parts: {name: value}}]. */
export function stackedBars(rows, colours, { width = 420, rowHeight = 18 } = {}) {
  const labelWidth = 90;
  const height = rows.length * (rowHeight + 4) + 24;
  const svg = node('svg', { width, height, viewBox: `0 0 ${width} ${height}`, role: 'img' });
  rows.forEach((row, i) => {
    const y = i * (rowHeight + 4);
    svg.append(node('text', { x: 0, y: y + rowHeight - 5, 'font-size': 11 }, row.label));
    const total = Object.values(row.parts).reduce((a, b) => a + b, 0) || 1;
    let x = labelWidth;
    for (const [part, colour] of Object.entries(colours)) {
      const partWidth = ((row.parts[part] ?? 0) / total) * (width - labelWidth);
      const rect = node('rect', { x, y, width: partWidth, height: rowHeight, fill: colour });
      rect.append(node('title', {}, `${row.label} ${part}: ${Math.round(((row.parts[part] ?? 0) / total) * 100)}%`));
      svg.append(rect);
      x += partWidth;
    }
  });
  let x = labelWidth;
  const legendY = rows.length * (rowHeight + 4) + 14;
  for (const [part, colour] of Object.entries(colours)) {
    svg.append(node('rect', { x, y: legendY - 9, width: 10, height: 10, fill: colour }));
    svg.append(node('text', { x: x + 14, y: legendY, 'font-size': 11 }, part));
    x += 75;
  }
  return svg;
}
