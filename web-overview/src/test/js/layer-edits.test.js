// Unit checks of the layer edits (node --test): visibility by layer and group, order, deletion with the elements.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import {
  addLayer, addLayerGroup, assignLayer, changeLayer, changeLayerGroup, deleteLayerGroup, deleteLayers, hiddenLayerIds,
  moveLayer, orderedLayers,
} from '../../main/resources/org/ktcs/overview/app/modelling/layer-edits.js';
import { addPath, addPoint, emptyModel } from '../../main/resources/org/ktcs/overview/app/modelling/model-edits.js';

function twoLayers() {
  const { model, id } = addLayer(emptyModel());
  let next = addPoint(model, 0, 0, 0).model;
  next = addPoint(next, 1000, 0, id).model;
  return addPath(next, 'Point-0001', 'Point-0002', id).model;
}

test('a layer is hidden when it or its group is', () => {
  let model = twoLayers();
  assert.deepEqual([...hiddenLayerIds(model)], []);
  model = changeLayer(model, 1, (l) => ({ ...l, visible: false }));
  assert.deepEqual([...hiddenLayerIds(model)], [1]);
  model = changeLayer(model, 1, (l) => ({ ...l, visible: true }));
  model = changeLayerGroup(model, 0, (g) => ({ ...g, visible: false }));
  assert.deepEqual([...hiddenLayerIds(model)], [0, 1]);
});

test('layers move in the order; a deleted layer takes its elements and the paths at them', () => {
  const model = twoLayers();
  assert.deepEqual(orderedLayers(moveLayer(model, 1, -1)).map((l) => l.id), [1, 0]);
  assert.equal(moveLayer(model, 0, -1), model);
  const without = deleteLayers(model, new Set([1]));
  assert.deepEqual(without.points.map((p) => p.name), ['Point-0001']);
  assert.equal(without.paths.length, 0);
  assert.deepEqual(without.visualLayout.layers.map((l) => l.id), [0]);
});

test('a layer group goes with its layers, but not the last group; elements are put on another layer', () => {
  let model = addLayerGroup(twoLayers());
  assert.deepEqual(deleteLayerGroup(model, 1).visualLayout.layerGroups.map((g) => g.id), [0]);
  model = changeLayer(model, 1, (l) => ({ ...l, groupId: 1 }));
  const without = deleteLayerGroup(model, 1);
  assert.deepEqual(without.visualLayout.layerGroups.map((g) => g.id), [0]);
  assert.deepEqual(without.points.map((p) => p.name), ['Point-0001']);
  assert.equal(deleteLayerGroup(without, 0), null);
  const moved = assignLayer(model, new Set(['point:Point-0001']), 1);
  assert.equal(moved.points[0].layout.layerId, 1);
});
