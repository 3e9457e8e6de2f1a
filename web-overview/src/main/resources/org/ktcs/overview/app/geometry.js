// The plant model as drawable geometry in model coordinates (mm, y up), with a grid index for culling and clicks.

import { pathLine, pointAtShare } from './path-shapes.js';

/** Builds points, paths, locations and blocks of a GET /v1/plantModel answer. */
export function buildGeometry(model) {
  const layout = model.visualLayout ?? { scaleX: 50, scaleY: 50, layers: [], layerGroups: [] };
  const points = new Map(model.points.map((p) => [p.name, {
    kind: 'point', name: p.name, x: p.position.x, y: p.position.y, type: p.type, layerId: p.layout?.layerId ?? 0,
  }]));
  const paths = model.paths.map((path) => pathGeometry(path, points, layout)).filter(Boolean);
  const locationTypes = new Map(model.locationTypes.map((t) => [t.name, t]));
  const locations = model.locations.map((l) => ({
    kind: 'location', dto: l, name: l.name, x: l.position.x, y: l.position.y, typeName: l.typeName, locked: l.locked,
    links: l.links.map((link) => points.get(link.pointName)).filter(Boolean), layerId: l.layout?.layerId ?? 0,
  }));
  const blockColours = new Map();
  for (const block of model.blocks) {
    for (const member of block.memberNames) blockColours.set(member, block.layout?.color ?? '#ff0000');
  }
  const geometry = {
    points, paths, pathsByName: new Map(paths.map((p) => [p.name, p])), locations,
    locationsByName: new Map(locations.map((l) => [l.name, l])), locationTypes, blockColours,
    layers: layout.layers ?? [], layerGroups: layout.layerGroups ?? [],
  };
  geometry.bounds = boundsOf([...points.values(), ...locations]);
  geometry.index = new GridIndex(geometry.bounds, [...points.values(), ...paths, ...locations]);
  return geometry;
}

function pathGeometry(path, points, layout) {
  const src = points.get(path.srcPointName);
  const dst = points.get(path.destPointName);
  if (!src || !dst) return null;
  // Control points are layout coordinates: model millimetres divided by the scale, with y pointing down.
  const controls = (path.layout?.controlPoints ?? []).map((c) => ({ x: c.x * layout.scaleX, y: -c.y * layout.scaleY }));
  const scale = { x: layout.scaleX, y: layout.scaleY };
  const line = pathLine(path.layout?.connectionType ?? 'DIRECT', src, controls, dst, scale);
  return {
    kind: 'path', name: path.name, src, dst, line, locked: path.locked, layerId: path.layout?.layerId ?? 0,
    forward: path.maxVelocity > 0, reverse: path.maxReverseVelocity > 0, bounds: boundsOf(line),
  };
}

export function boundsOf(items) {
  const bounds = { minX: Infinity, minY: Infinity, maxX: -Infinity, maxY: -Infinity };
  for (const item of items) {
    const b = item.bounds ?? { minX: item.x, minY: item.y, maxX: item.x, maxY: item.y };
    bounds.minX = Math.min(bounds.minX, b.minX);
    bounds.minY = Math.min(bounds.minY, b.minY);
    bounds.maxX = Math.max(bounds.maxX, b.maxX);
    bounds.maxY = Math.max(bounds.maxY, b.maxY);
  }
  if (!Number.isFinite(bounds.minX)) return { minX: 0, minY: 0, maxX: 10000, maxY: 10000 };
  return bounds;
}

/** The middle of a path's drawn line and the direction there. */
export function midpointOf(path) {
  const middle = pointAtShare(path.line, 0.5);
  return { x: middle.x, y: middle.y, angle: middle.heading };
}

/** Distance from (x, y) to a polyline. */
export function distanceToLine(line, x, y) {
  let best = Infinity;
  for (let i = 1; i < line.length; i += 1) best = Math.min(best, distanceToSegment(line[i - 1], line[i], x, y));
  return best;
}

function distanceToSegment(a, b, x, y) {
  const dx = b.x - a.x;
  const dy = b.y - a.y;
  const lengthSquared = dx * dx + dy * dy;
  const t = lengthSquared === 0 ? 0 : Math.max(0, Math.min(1, ((x - a.x) * dx + (y - a.y) * dy) / lengthSquared));
  return Math.hypot(a.x + t * dx - x, a.y + t * dy - y);
}

/** Buckets items by the grid cells their bounds touch, so a view or a click looks only at what is near. */
class GridIndex {
  constructor(bounds, items) {
    this.bounds = bounds;
    const width = Math.max(1, bounds.maxX - bounds.minX);
    const height = Math.max(1, bounds.maxY - bounds.minY);
    this.columns = Math.max(1, Math.min(256, Math.ceil(Math.sqrt(items.length * width / height) / 2)));
    this.rows = Math.max(1, Math.min(256, Math.ceil(Math.sqrt(items.length * height / width) / 2)));
    this.cellWidth = width / this.columns;
    this.cellHeight = height / this.rows;
    this.cells = new Map();
    items.forEach((item) => this.insert(item));
  }

  insert(item) {
    const b = item.bounds ?? { minX: item.x, minY: item.y, maxX: item.x, maxY: item.y };
    this.forCells(b, (key) => {
      let cell = this.cells.get(key);
      if (!cell) this.cells.set(key, (cell = []));
      cell.push(item);
    });
  }

  /** Every item whose bounds may touch the rectangle, once each. */
  query(rect) {
    const found = new Set();
    this.forCells(rect, (key) => this.cells.get(key)?.forEach((item) => found.add(item)));
    return found;
  }

  forCells(rect, visit) {
    const column = (x) => Math.max(0, Math.min(this.columns - 1, Math.floor((x - this.bounds.minX) / this.cellWidth)));
    const row = (y) => Math.max(0, Math.min(this.rows - 1, Math.floor((y - this.bounds.minY) / this.cellHeight)));
    for (let c = column(rect.minX); c <= column(rect.maxX); c += 1) {
      for (let r = row(rect.minY); r <= row(rect.maxY); r += 1) visit(c * 65536 + r);
    }
  }
}
