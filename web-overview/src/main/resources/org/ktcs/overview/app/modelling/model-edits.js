// Edits of a plant model as the web API's JSON holds it (GET /v1/plantModel). Every edit answers a new model and
// leaves the old one as it was, so undo keeps old models and the drawing rebuilds only from the new one.

/** @typedef {{x: number, y: number, z?: number}} Position */
/** @typedef {{name: string, position: Position, type: string, vehicleOrientationAngle: number|string, layout: any, properties: any[]}} PointJson */
/** @typedef {{name: string, srcPointName: string, destPointName: string, length: number, maxVelocity: number, maxReverseVelocity: number, locked: boolean, layout: {connectionType: string, controlPoints: {x: number, y: number}[], layerId: number}, properties: any[]}} PathJson */
/** @typedef {{name: string, points: PointJson[], paths: PathJson[], locations: any[], locationTypes: any[], blocks: any[], vehicles: any[], visualLayout: any, properties: any[]}} ModelJson */

import { nextName, pathName } from './naming.js';
import { lineLength, pathLine } from '../path-shapes.js';

/** @returns {ModelJson} a model without elements, with openTCS's default layer. */
export function emptyModel(name = 'Unnamed model') {
  return {
    name, points: [], paths: [], locations: [], locationTypes: [], blocks: [], vehicles: [], properties: [],
    visualLayout: {
      name: 'VLayout-01', scaleX: 50, scaleY: 50, properties: [],
      layers: [{ id: 0, ordinal: 0, visible: true, name: 'Default layer', groupId: 0 }],
      layerGroups: [{ id: 0, name: 'Default layer group', visible: true }],
    },
  };
}

/** The kinds of the model's named lists, by the kind names the overview selects with. */
export const LISTS = {
  point: 'points', path: 'paths', location: 'locations', locationType: 'locationTypes', block: 'blocks', vehicle: 'vehicles',
};

/** @returns {{model: ModelJson, name: string}} */
export function addPoint(model, x, y, layerId = 0) {
  const name = nextName('Point-', model.points);
  const point = {
    name, position: { x: Math.round(x), y: Math.round(y), z: 0 }, vehicleOrientationAngle: 'NaN', type: 'HALT_POSITION',
    layout: { position: { x: 0, y: 0 }, labelOffset: { x: -10, y: -20 }, layerId }, vehicleEnvelopes: [],
    maxVehicleBoundingBox: { length: 1000, width: 1000, height: 1000, referenceOffset: { x: 0, y: 0 } }, properties: [],
  };
  return { model: { ...model, points: [...model.points, point] }, name };
}

/** A path from [src] to [dst], forward only, its length the distance between them. Null if it exists already. */
export function addPath(model, src, dst, layerId = 0) {
  const name = pathName(src, dst);
  if (src === dst || model.paths.some((p) => p.name === name)) return null;
  const path = {
    name, srcPointName: src, destPointName: dst, length: 1, maxVelocity: 1000, maxReverseVelocity: 0,
    peripheralOperations: [], locked: false, vehicleEnvelopes: [], properties: [],
    layout: { connectionType: 'DIRECT', controlPoints: [], layerId },
  };
  path.length = pathLength(model, path);
  return { model: { ...model, paths: [...model.paths, path] }, name };
}

/** A location of [typeName] (a new location type if the model has none), linked to [linkTo] if given. */
export function addLocation(model, x, y, linkTo = null, layerId = 0) {
  let next = model;
  if (next.locationTypes.length === 0) next = addLocationType(next).model;
  const name = nextName('Location-', next.locations);
  const type = next.locationTypes[0];
  const location = {
    name, typeName: type.name, position: { x: Math.round(x), y: Math.round(y), z: 0 }, locked: false, properties: [],
    links: linkTo ? [{ pointName: linkTo, allowedOperations: [] }] : [],
    layout: { position: { x: 0, y: 0 }, labelOffset: { x: -10, y: -20 }, locationRepresentation: 'DEFAULT', layerId },
  };
  return { model: { ...next, locations: [...next.locations, location] }, name };
}

export function addLocationType(model) {
  const name = nextName('LType-', model.locationTypes);
  const type = {
    name, allowedOperations: ['NOP'], allowedPeripheralOperations: [], properties: [],
    layout: { locationRepresentation: 'NONE' },
  };
  return { model: { ...model, locationTypes: [...model.locationTypes, type] }, name };
}

export function addVehicle(model) {
  const name = nextName('Vehicle-', model.vehicles);
  const vehicle = {
    name, length: 1000, energyLevelCritical: 30, energyLevelGood: 90, energyLevelFullyRecharged: 90,
    energyLevelSufficientlyRecharged: 30, maxVelocity: 1000, maxReverseVelocity: 1000, envelopeKey: null,
    layout: { routeColor: '#00FF00' }, properties: [],
  };
  return { model: { ...model, vehicles: [...model.vehicles, vehicle] }, name };
}

export function addBlock(model, memberNames = []) {
  const name = nextName('Block-', model.blocks);
  const block = { name, type: 'SINGLE_VEHICLE_ONLY', layout: { color: '#FF0000' }, memberNames, properties: [] };
  return { model: { ...model, blocks: [...model.blocks, block] }, name };
}

/** Links location [location] to point [point] (no-op if linked). */
export function addLink(model, location, point) {
  return replaceNamed(model, 'location', location, (l) => (l.links.some((k) => k.pointName === point)
    ? l : { ...l, links: [...l.links, { pointName: point, allowedOperations: [] }] }));
}

/** Replaces the element [name] of [kind] with what [change] answers for it. */
export function replaceNamed(model, kind, name, change) {
  const list = LISTS[kind];
  return { ...model, [list]: model[list].map((e) => (e.name === name ? change(e) : e)) };
}

/**
 * Moves points and locations (a set of "kind:name" keys) by (dx, dy) mm; the lengths of the paths at moved points
 * are not recomputed (openTCS recomputes them on demand).
 */
export function moveElements(model, keys, dx, dy) {
  const move = (kind) => (e) => (keys.has(`${kind}:${e.name}`)
    ? { ...e, position: { ...e.position, x: Math.round(e.position.x + dx), y: Math.round(e.position.y + dy) } } : e);
  return { ...model, points: model.points.map(move('point')), locations: model.locations.map(move('location')) };
}

/**
 * Deletes the selected elements ("kind:name" keys) and what depends on them: the paths at a deleted point, the links
 * to it, a deleted location type's locations, block memberships of anything deleted.
 */
export function deleteElements(model, keys) {
  const gone = (kind, name) => keys.has(`${kind}:${name}`);
  const points = model.points.filter((p) => !gone('point', p.name));
  const kept = new Set(points.map((p) => p.name));
  const locationTypes = model.locationTypes.filter((t) => !gone('locationType', t.name));
  const types = new Set(locationTypes.map((t) => t.name));
  const paths = model.paths.filter((p) => !gone('path', p.name) && kept.has(p.srcPointName) && kept.has(p.destPointName));
  const locations = model.locations.filter((l) => !gone('location', l.name) && types.has(l.typeName))
    .map((l) => ({ ...l, links: l.links.filter((k) => kept.has(k.pointName)) }));
  const members = new Set([...points, ...paths, ...locations].map((e) => e.name));
  const blocks = model.blocks.filter((b) => !gone('block', b.name))
    .map((b) => ({ ...b, memberNames: b.memberNames.filter((m) => members.has(m)) }));
  const vehicles = model.vehicles.filter((v) => !gone('vehicle', v.name));
  return { ...model, points, paths, locations, locationTypes, blocks, vehicles };
}

/** The length of [path] in mm along its drawn line (straight, or its curve through the control points). */
export function pathLength(model, path) {
  const points = new Map(model.points.map((p) => [p.name, p.position]));
  const src = points.get(path.srcPointName);
  const dst = points.get(path.destPointName);
  if (!src || !dst) return path.length;
  const scaleX = model.visualLayout?.scaleX ?? 50;
  const scaleY = model.visualLayout?.scaleY ?? 50;
  const controls = (path.layout?.controlPoints ?? []).map((c) => ({ x: c.x * scaleX, y: -c.y * scaleY }));
  const line = pathLine(path.layout?.connectionType ?? 'DIRECT', src, controls, dst, { x: scaleX, y: scaleY }, 64);
  return Math.max(1, Math.round(lineLength(line)));
}

/** Recomputes the length of every path (of [names] only, if given) from its geometry. */
export function recomputeLengths(model, names = null) {
  return {
    ...model,
    paths: model.paths.map((p) => (names && !names.has(p.name) ? p : { ...p, length: pathLength(model, p) })),
  };
}

/** Renames element [from] of [kind] to [to] and every reference to it (paths' ends, links, types, block members). */
export function renameElement(model, kind, from, to) {
  const renamed = replaceNamed(model, kind, from, (e) => ({ ...e, name: to }));
  const swap = (name) => (name === from ? to : name);
  return {
    ...renamed,
    paths: kind === 'point' ? renamed.paths.map((p) => ({ ...p, srcPointName: swap(p.srcPointName), destPointName: swap(p.destPointName) })) : renamed.paths,
    locations: renamed.locations.map((l) => ({
      ...l,
      typeName: kind === 'locationType' ? swap(l.typeName) : l.typeName,
      links: kind === 'point' ? l.links.map((k) => ({ ...k, pointName: swap(k.pointName) })) : l.links,
    })),
    blocks: renamed.blocks.map((b) => ({ ...b, memberNames: b.memberNames.map(swap) })),
  };
}
