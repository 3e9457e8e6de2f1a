// The line a path is drawn (and measured) along, for each of openTCS's connection types, in model mm (y up).
// openTCS's Model Editor draws paths with JHotDraw's liners between point figures: ELBOW is an axis-parallel dog-leg
// (vertical from the source to half-way, horizontal, vertical to the destination), SLANTED a short horizontal stub of
// 20 drawing units at each end, towards the other end, joined by a slanted line; neither uses control points. POLYPATH
// runs through its control points, BEZIER is a cubic curve with two control points, BEZIER_3 two cubic curves joined
// at the third of its five control points.

/** @typedef {{x: number, y: number}} Xy */

/** The length of SLANTED's stubs, in layout units (openTCS's drawing pixels: model mm divided by the scale). */
export const SLANT_LAYOUT_UNITS = 20;

/** Where openTCS's Model Editor puts a new path's control points, as fractions of the straight line. */
const DEFAULT_CONTROLS = { BEZIER: [1 / 3, 2 / 3], BEZIER_3: [1 / 6, 2 / 6, 3 / 6, 4 / 6, 5 / 6], POLYPATH: [0.5] };

/**
 * The fractions of the straight line at which a path of [type] gets control points when it has the wrong number of
 * them; an empty list for the types that use none.
 * @param {string} type
 * @returns {number[]}
 */
export function defaultControlFractions(type) {
  return DEFAULT_CONTROLS[type] ?? [];
}

/**
 * Whether a path of [type] with [count] control points keeps them: BEZIER needs one or two, BEZIER_3 five, POLYPATH
 * at least one; the others use none.
 * @param {string} type
 * @param {number} count
 */
export function controlsFit(type, count) {
  if (type === 'BEZIER') return count === 1 || count === 2;
  if (type === 'BEZIER_3') return count === 5;
  if (type === 'POLYPATH') return count >= 1;
  return count === 0;
}

/**
 * The polyline a path of connection [type] is drawn along, from [src] to [dst].
 * @param {string} type
 * @param {Xy} src
 * @param {Xy[]} controls the control points, in model mm
 * @param {Xy} dst
 * @param {{x: number, y: number}} scale the layout's scale (mm per layout unit)
 * @param {number} segments how many straight pieces approximate each cubic curve
 * @returns {Xy[]}
 */
export function pathLine(type, src, controls, dst, scale = { x: 50, y: 50 }, segments = 12) {
  if (type === 'ELBOW') return elbow(src, dst);
  if (type === 'SLANTED') return slanted(src, dst, scale);
  if (type === 'POLYPATH' && controls.length > 0) return [src, ...controls, dst];
  if (type === 'BEZIER_3' && controls.length === 5) {
    return [...cubic(src, controls[0], controls[1], controls[2], segments),
      ...cubic(controls[2], controls[3], controls[4], dst, segments).slice(1)];
  }
  if ((type === 'BEZIER' || type === 'BEZIER_3') && controls.length > 0) {
    return cubic(src, controls[0], controls[controls.length > 1 ? 1 : 0], dst, segments);
  }
  return [src, dst];
}

/** @param {Xy} src @param {Xy} dst @returns {Xy[]} */
function elbow(src, dst) {
  if (src.x === dst.x || src.y === dst.y) return [src, dst];
  const middle = (src.y + dst.y) / 2;
  return [src, { x: src.x, y: middle }, { x: dst.x, y: middle }, dst];
}

/** @param {Xy} src @param {Xy} dst @param {{x: number, y: number}} scale @returns {Xy[]} */
function slanted(src, dst, scale) {
  if (src.x !== dst.x) {
    const stub = Math.sign(dst.x - src.x) * SLANT_LAYOUT_UNITS * scale.x;
    return [src, { x: src.x + stub, y: src.y }, { x: dst.x - stub, y: dst.y }, dst];
  }
  if (src.y === dst.y) return [src, dst];
  const stub = Math.sign(dst.y - src.y) * SLANT_LAYOUT_UNITS * scale.y;
  return [src, { x: src.x, y: src.y + stub }, { x: dst.x, y: dst.y - stub }, dst];
}

/** @param {Xy} a @param {Xy} b @param {Xy} c @param {Xy} d @param {number} segments @returns {Xy[]} */
function cubic(a, b, c, d, segments) {
  const line = [];
  for (let i = 0; i <= segments; i += 1) {
    const t = i / segments;
    const u = 1 - t;
    line.push({
      x: u * u * u * a.x + 3 * u * u * t * b.x + 3 * u * t * t * c.x + t * t * t * d.x,
      y: u * u * u * a.y + 3 * u * u * t * b.y + 3 * u * t * t * c.y + t * t * t * d.y,
    });
  }
  return line;
}

/**
 * The length of a polyline.
 * @param {Xy[]} line
 */
export function lineLength(line) {
  let length = 0;
  for (let i = 1; i < line.length; i += 1) length += Math.hypot(line[i].x - line[i - 1].x, line[i].y - line[i - 1].y);
  return length;
}

/**
 * The point at [share] of [line]'s length, and the line's heading there (radians).
 * @param {Xy[]} line
 * @param {number} share
 */
export function pointAtShare(line, share) {
  // Two passes without allocating: the overview calls this for every path in view on every frame (its arrow).
  const segment = (i) => Math.hypot(line[i].x - line[i - 1].x, line[i].y - line[i - 1].y);
  let remaining = 0;
  for (let i = 1; i < line.length; i += 1) remaining += segment(i);
  remaining *= share;
  for (let i = 1; i < line.length; i += 1) {
    const [a, b] = [line[i - 1], line[i]];
    const length = segment(i);
    if (remaining <= length || i === line.length - 1) {
      const t = length === 0 ? 0 : Math.min(1, remaining / length);
      return { x: a.x + (b.x - a.x) * t, y: a.y + (b.y - a.y) * t, heading: Math.atan2(b.y - a.y, b.x - a.x) };
    }
    remaining -= length;
  }
  return { x: line[0].x, y: line[0].y, heading: 0 };
}
