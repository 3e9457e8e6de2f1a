// Unit checks of the paths' geometry (node --test; run by JavaScriptChecksTest): the lines openTCS's connection
// types are drawn along, the lengths measured along them, and the control points a new curve gets.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { controlsFit, lineLength, pathLine } from '../../main/resources/org/ktcs/overview/app/path-shapes.js';
import { withConnectionType } from '../../main/resources/org/ktcs/overview/app/modelling/control-points.js';
import { addPath, addPoint, emptyModel, pathLength } from '../../main/resources/org/ktcs/overview/app/modelling/model-edits.js';

const scale = { x: 50, y: 50 };
const src = { x: 0, y: 0 };
const dst = { x: 4000, y: 3000 };

test('ELBOW is an axis-parallel dog-leg: vertical to half-way, horizontal, vertical', () => {
  assert.deepEqual(pathLine('ELBOW', src, [], dst, scale),
    [src, { x: 0, y: 1500 }, { x: 4000, y: 1500 }, dst]);
  assert.equal(lineLength(pathLine('ELBOW', src, [], dst, scale)), 7000);
  // Aligned ends need no corner; control points do not bend it.
  assert.deepEqual(pathLine('ELBOW', src, [{ x: 9, y: 9 }], { x: 0, y: 5000 }, scale), [src, { x: 0, y: 5000 }]);
});

test('SLANTED has a 20-unit horizontal stub at each end, towards the other end, joined by a slanted line', () => {
  assert.deepEqual(pathLine('SLANTED', src, [], dst, scale),
    [src, { x: 1000, y: 0 }, { x: 3000, y: 3000 }, dst]);
  assert.deepEqual(pathLine('SLANTED', dst, [], src, { x: 10, y: 10 }),
    [dst, { x: 3800, y: 3000 }, { x: 200, y: 0 }, src]);
  assert.deepEqual(pathLine('SLANTED', src, [], { x: 0, y: -5000 }, scale),
    [src, { x: 0, y: -1000 }, { x: 0, y: -4000 }, { x: 0, y: -5000 }]);
});

test('BEZIER_3 is two cubic curves joined at its third control point; BEZIER one through its ends', () => {
  const controls = [{ x: 0, y: 1000 }, { x: 1000, y: 2000 }, { x: 2000, y: 2000 }, { x: 3000, y: 2000 }, { x: 4000, y: 1000 }];
  const line = pathLine('BEZIER_3', src, controls, dst, scale, 8);
  assert.equal(line.length, 17);
  assert.deepEqual(line[0], src);
  assert.deepEqual(line[8], controls[2]);
  assert.deepEqual(line[16], dst);
  const bezier = pathLine('BEZIER', src, [{ x: 0, y: 3000 }, { x: 4000, y: 0 }], dst, scale, 2);
  assert.deepEqual(bezier, [src, { x: 2000, y: 1500 }, dst]);
  assert.deepEqual(pathLine('POLYPATH', src, [{ x: 0, y: 3000 }], dst, scale), [src, { x: 0, y: 3000 }, dst]);
  assert.deepEqual(pathLine('DIRECT', src, [{ x: 0, y: 3000 }], dst, scale), [src, dst]);
});

/** A model with two points and a DIRECT path between them. */
function twoPoints() {
  let model = addPoint(emptyModel(), 0, 0).model;
  model = addPoint(model, 6000, 3000).model;
  return addPath(model, 'Point-0001', 'Point-0002').model;
}

test('a path made BEZIER_3 gets five control points along its line, at every sixth; DIRECT drops them', () => {
  const model = twoPoints();
  const curved = withConnectionType(model, model.paths[0], 'BEZIER_3');
  // Layout units: mm divided by the scale (50), y pointing down.
  assert.deepEqual(curved.layout.controlPoints,
    [{ x: 20, y: -10 }, { x: 40, y: -20 }, { x: 60, y: -30 }, { x: 80, y: -40 }, { x: 100, y: -50 }]);
  assert.equal(controlsFit('BEZIER_3', 5), true);
  assert.equal(withConnectionType(model, curved, 'BEZIER').layout.controlPoints.length, 2);
  assert.deepEqual(withConnectionType(model, curved, 'DIRECT').layout.controlPoints, []);
  assert.deepEqual(withConnectionType(model, curved, 'ELBOW').layout.controlPoints, []);
});

test('path lengths are measured along the drawn line', () => {
  const model = twoPoints();
  const path = model.paths[0];
  assert.equal(pathLength(model, path), Math.round(Math.hypot(6000, 3000)));
  assert.equal(pathLength(model, withConnectionType(model, path, 'ELBOW')), 9000);
  assert.equal(pathLength(model, withConnectionType(model, path, 'SLANTED')), Math.round(2000 + Math.hypot(4000, 3000)));
  // Control points on the straight line leave a curve as long as the line.
  assert.equal(pathLength(model, withConnectionType(model, path, 'BEZIER_3')), Math.round(Math.hypot(6000, 3000)));
});

test('a vehicle reported on the straight line between an ELBOW path\'s ends is drawn on the dog-leg', async () => {
  const { onDrawnPath } = await import('../../main/resources/org/ktcs/overview/app/drawn-position.js');
  const line = pathLine('ELBOW', src, [], dst, scale);
  const geometry = { pathsByName: new Map([['A --- B', { src, dst, line }], ['B --- C', { src: dst, dst, line: [dst, dst] }]]) };
  // A quarter of the way along the chord is a quarter of the dog-leg's 7000 mm: 1500 up, then 250 to the right.
  const quarter = onDrawnPath(geometry, [['B --- C'], ['A --- B']], { x: 1000, y: 750 }, 36.87);
  assert.deepEqual({ x: quarter.x, y: quarter.y }, { x: 250, y: 1500 });
  // Heading east on the horizontal leg: the reported chord heading turned by the leg's direction.
  assert.ok(Math.abs(quarter.angle) < 0.01);
  assert.equal(onDrawnPath(geometry, [['A --- B']], { x: 1000, y: 2000 }, 0), null, 'off the chord');
  assert.equal(onDrawnPath(geometry, [], { x: 1000, y: 750 }, 0), null, 'not on an allocated path');
});
