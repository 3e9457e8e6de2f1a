// Unit checks of the overview's WebSocket state (node --test): events that leave out unchanged fields are completed
// from the object's state before, so the state and every listener see whole objects.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { KtcsClient } from '../../main/resources/org/ktcs/overview/app/client.js';

const order = {
  name: 'T1', state: 'BEING_PROCESSED', currentRouteStepIndex: 2, properties: { k: 'v' },
  driveOrders: [{ name: 'D1', route: { steps: [{ destinationPoint: 'B' }] } }],
};

test('an event without its unchanged fields keeps them from the state before', () => {
  const client = new KtcsClient();
  const seen = [];
  client.listeners.get('transportOrders').add((message) => {
    if (message.type === 'event') seen.push(message.current);
  });
  client.receive({ type: 'snapshot', topic: 'transportOrders', objects: [order] });

  client.receive({
    type: 'event', topic: 'transportOrders', seq: 1, previous: null,
    current: { name: 'T1', state: 'BEING_PROCESSED', currentRouteStepIndex: 3 },
    unchanged: ['driveOrders', 'properties'],
  });

  const now = client.state.get('transportOrders').get('T1');
  assert.equal(now.currentRouteStepIndex, 3);
  assert.deepEqual(now.driveOrders, order.driveOrders);
  assert.deepEqual(now.properties, { k: 'v' });
  assert.deepEqual(seen[0].driveOrders, order.driveOrders);
});

test('an event with every field replaces the object as before', () => {
  const client = new KtcsClient();
  client.receive({ type: 'snapshot', topic: 'transportOrders', objects: [order] });

  client.receive({
    type: 'event', topic: 'transportOrders', seq: 1, previous: null,
    current: { ...order, driveOrders: [] },
  });

  assert.deepEqual(client.state.get('transportOrders').get('T1').driveOrders, []);
});

test('a shortened resource list is the list before without its first entries', () => {
  const client = new KtcsClient();
  const vehicle = {
    name: 'V1', currentPosition: 'A', properties: {},
    claimedResources: [['A-B', 'B'], ['B-C', 'C'], ['C-D', 'D']], allocatedResources: [['A']],
  };
  client.receive({ type: 'snapshot', topic: 'vehicles', objects: [vehicle] });

  client.receive({
    type: 'event', topic: 'vehicles', seq: 1, previous: null,
    current: { name: 'V1', currentPosition: 'A', allocatedResources: [['A'], ['A-B', 'B']] },
    unchanged: ['properties'], shortened: { claimedResources: 1 },
  });

  const now = client.state.get('vehicles').get('V1');
  assert.deepEqual(now.claimedResources, [['B-C', 'C'], ['C-D', 'D']]);
  assert.deepEqual(now.allocatedResources, [['A'], ['A-B', 'B']]);
  assert.deepEqual(vehicle.claimedResources.length, 3, 'the state before is not changed in place');
});

test('an event with only what changed is merged into the object before; a field sent as null is cleared', () => {
  const client = new KtcsClient();
  const seen = [];
  client.listeners.get('vehicles').add((message) => {
    if (message.type === 'event') seen.push(message.current);
  });
  const vehicle = {
    name: 'V1', currentPosition: 'A', state: { state: 'EXECUTING' }, waitingReason: 'blocked by V2',
    allocatedResources: [['A'], ['A-B', 'B']], claimedResources: [['B-C', 'C']],
  };
  client.receive({ type: 'snapshot', topic: 'vehicles', objects: [vehicle] });

  client.receive({
    type: 'event', topic: 'vehicles', seq: 1, previous: null,
    current: { name: 'V1', currentPosition: 'B', waitingReason: null }, shortened: { allocatedResources: 1 },
  });

  const now = client.state.get('vehicles').get('V1');
  assert.equal(now.currentPosition, 'B');
  assert.equal(now.waitingReason, null);
  assert.deepEqual(now.state, { state: 'EXECUTING' });
  assert.deepEqual(now.allocatedResources, [['A-B', 'B']]);
  assert.deepEqual(now.claimedResources, [['B-C', 'C']]);
  assert.equal(seen[0], now, 'listeners get the merged object');
  assert.equal(vehicle.currentPosition, 'A', 'the state before is not changed in place');
});

test('a vehicle the client has not seen yet comes whole, and a removed one goes', () => {
  const client = new KtcsClient();
  client.receive({ type: 'snapshot', topic: 'vehicles', objects: [] });

  client.receive({
    type: 'event', topic: 'vehicles', seq: 1, previous: null, current: { name: 'V2', currentPosition: 'C' },
  });
  assert.equal(client.state.get('vehicles').get('V2').currentPosition, 'C');

  client.receive({ type: 'event', topic: 'vehicles', seq: 2, previous: { name: 'V2' }, current: null });
  assert.equal(client.state.get('vehicles').has('V2'), false);
});
