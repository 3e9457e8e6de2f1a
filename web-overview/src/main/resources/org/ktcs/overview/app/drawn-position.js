// Where a vehicle driving a path that is not drawn straight (ELBOW, SLANTED, curves) is drawn. Drivers such as the
// loopback report precise positions on the straight line between the path's ends; the overview moves such a position
// to the same share of the drawn line, so the vehicle follows the path as it is drawn.

import { pointAtShare } from './path-shapes.js';

/** @typedef {{x: number, y: number}} Xy */

/** How far (mm) a reported position may lie off the straight line between a path's ends and still be on it. */
const ON_CHORD_MM = 5;

/**
 * [position] moved onto the drawn line of the non-straight path among [resources] (the vehicle's allocated resource
 * names) whose straight line it lies on, with [angle] turned as the drawn line turns there; null if there is none.
 * @param {{pathsByName: Map<string, any>}} geometry
 * @param {string[][]} resources
 * @param {Xy} position
 * @param {number} angle the reported orientation in degrees (NaN: unknown)
 * @returns {{x: number, y: number, angle: number}|null}
 */
export function onDrawnPath(geometry, resources, position, angle) {
  for (const set of resources ?? []) {
    for (const name of set) {
      const path = geometry.pathsByName.get(name);
      if (!path || path.line.length <= 2) continue;
      const share = shareOfChord(path.src, path.dst, position);
      if (share === null) continue;
      const at = pointAtShare(path.line, share);
      const chord = Math.atan2(path.dst.y - path.src.y, path.dst.x - path.src.x);
      const turned = Number.isFinite(angle) ? angle + ((at.heading - chord) * 180) / Math.PI : angle;
      return { x: at.x, y: at.y, angle: turned };
    }
  }
  return null;
}

/** The share (0..1) of the way from [a] to [b] at which [p] lies on the straight line between them, or null. */
function shareOfChord(a, b, p) {
  const dx = b.x - a.x;
  const dy = b.y - a.y;
  const length = Math.hypot(dx, dy);
  if (length === 0) return null;
  const share = ((p.x - a.x) * dx + (p.y - a.y) * dy) / (length * length);
  const off = Math.abs((p.x - a.x) * dy - (p.y - a.y) * dx) / length;
  return share >= 0 && share <= 1 && off <= ON_CHORD_MM ? share : null;
}
