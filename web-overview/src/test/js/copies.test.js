// Unit checks of copy and paste (node --test): copies are named by openTCS's naming schemes, and references between
// copied elements point at the copies.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { pasteCopies } from '../../main/resources/org/ktcs/overview/app/modelling/copies.js';
import {
  addBlock, addLink, addLocation, addPath, addPoint, addVehicle, emptyModel,
} from '../../main/resources/org/ktcs/overview/app/modelling/model-edits.js';

function plant() {
  let model = addPoint(emptyModel(), 0, 0).model;
  model = addPoint(model, 1000, 0).model;
  model = addPath(model, 'Point-0001', 'Point-0002').model;
  model = addLocation(model, 0, 1000, 'Point-0001').model;
  model = addVehicle(model).model;
  model = { ...model, vehicles: model.vehicles.map((v) => ({ ...v, maxVelocity: 1234, properties: [{ name: 'k', value: 'v' }] })) };
  return addBlock(model, ['Point-0001', 'Point-0001 --- Point-0002']).model;
}

test('a copied vehicle, location type and block are named by the naming schemes and keep their fields', () => {
  const model = plant();
  const keys = new Set(['vehicle:Vehicle-0001', 'locationType:LType-0001', 'block:Block-0001']);
  const pasted = pasteCopies(model, model, keys, 500, 500);
  assert.deepEqual([...pasted.keys].sort(), ['block:Block-0002', 'locationType:LType-0002', 'vehicle:Vehicle-0002']);
  const vehicle = pasted.model.vehicles.find((v) => v.name === 'Vehicle-0002');
  assert.equal(vehicle.maxVelocity, 1234);
  assert.deepEqual(vehicle.properties, [{ name: 'k', value: 'v' }]);
  // A block copied without its members has the same members.
  assert.deepEqual(pasted.model.blocks[1].memberNames, ['Point-0001', 'Point-0001 --- Point-0002']);
  assert.deepEqual(pasted.model.locationTypes[1].allowedOperations, pasted.model.locationTypes[0].allowedOperations);
});

test('copied together, a block has the copied members and a location the copied type and link', () => {
  const model = addLink(plant(), 'Location-0001', 'Point-0002');
  const keys = new Set(['point:Point-0001', 'point:Point-0002', 'location:Location-0001', 'locationType:LType-0001', 'block:Block-0001']);
  const pasted = pasteCopies(model, model, keys, 500, -500).model;
  assert.deepEqual(pasted.blocks[1].memberNames, ['Point-0003', 'Point-0003 --- Point-0004']);
  const location = pasted.locations.find((l) => l.name === 'Location-0002');
  assert.equal(location.typeName, 'LType-0002');
  assert.deepEqual(location.links.map((k) => k.pointName), ['Point-0003', 'Point-0004']);
  assert.deepEqual(location.position, { x: 500, y: 500, z: 0 });
  assert.equal(pasted.paths.length, 2);
});
