// The typed fields of each kind of element in the property panel: how to read a value from the element's JSON, how
// to write it back, and what makes a value invalid (checked as the user types, before anything changes).

import { withConnectionType } from './control-points.js';
import { LISTS } from './model-edits.js';

/**
 * @typedef {{key: string, label: string, type: 'text'|'number'|'select'|'checkbox'|'color'|'list',
 *   get: (e: any) => any, set?: (e: any, v: any, model: any) => any, options?: (model: any) => string[],
 *   check?: (v: any, e: any, model: any) => string|null, readOnly?: boolean,
 *   optionLabel?: (model: any, value: string) => string}} Field
 */
const REPRESENTATIONS = ['NONE', 'DEFAULT', 'LOAD_TRANSFER_GENERIC', 'LOAD_TRANSFER_ALT_1', 'LOAD_TRANSFER_ALT_2',
  'LOAD_TRANSFER_ALT_3', 'LOAD_TRANSFER_ALT_4', 'LOAD_TRANSFER_ALT_5', 'WORKING_GENERIC', 'WORKING_ALT_1',
  'WORKING_ALT_2', 'RECHARGE_GENERIC', 'RECHARGE_ALT_1', 'RECHARGE_ALT_2'];
const CONNECTION_TYPES = ['DIRECT', 'ELBOW', 'SLANTED', 'POLYPATH', 'BEZIER', 'BEZIER_3'];

const atLeast = (min) => (v) => (Number.isFinite(v) && v >= min ? null : `must be a number of at least ${min}`);
const percent = (v) => (Number.isInteger(v) && v >= 0 && v <= 100 ? null : 'must be a whole number from 0 to 100');
const whole = (v) => (Number.isInteger(v) ? null : 'must be a whole number');

/** A number field for [path] (e.g. "position.x") of the element. */
/** @returns {Field} */
function number(key, label, check = whole) {
  const parts = key.split('.');
  return {
    key, label, type: 'number', check,
    get: (e) => parts.reduce((o, p) => o?.[p], e),
    set: (e, v) => setIn(e, parts, v),
  };
}

/**
 * @param {any} object
 * @param {string[]} path
 * @param {any} value
 * @returns {any}
 */
function setIn(object, [first, ...rest], value) {
  return { ...object, [first]: rest.length ? setIn(object[first] ?? {}, rest, value) : value };
}

/** @returns {Field} */
function choice(key, label, options) {
  const parts = key.split('.');
  return { key, label, type: 'select', options, get: (e) => parts.reduce((o, p) => o?.[p], e), set: (e, v) => setIn(e, parts, v) };
}

/** A comma-separated list of names. */
/** @returns {Field} */
function list(key, label) {
  return {
    key, label, type: 'list',
    get: (e) => (e[key] ?? []).join(', '),
    set: (e, v) => ({ ...e, [key]: v.split(',').map((s) => s.trim()).filter(Boolean) }),
  };
}

const layer = choice('layout.layerId', 'Layer', (model) => (model.visualLayout?.layers ?? []).map((l) => String(l.id)));
layer.set = (e, v) => setIn(e, ['layout', 'layerId'], Number(v));
layer.get = (e) => String(e.layout?.layerId ?? 0);
layer.optionLabel = (model, id) => model.visualLayout?.layers?.find((l) => String(l.id) === id)?.name ?? id;

/** @type {Field} */
const orientation = {
  key: 'vehicleOrientationAngle', label: 'Vehicle orientation (°, empty: any)', type: 'text',
  get: (e) => (e.vehicleOrientationAngle === 'NaN' || Number.isNaN(e.vehicleOrientationAngle) ? '' : String(e.vehicleOrientationAngle)),
  set: (e, v) => ({ ...e, vehicleOrientationAngle: v.trim() === '' ? 'NaN' : Number(v) }),
  check: (v) => (v.trim() === '' || Number.isFinite(Number(v)) ? null : 'must be an angle in degrees, or empty'),
};

/** @type {Field} */
const controlPoints = {
  key: 'controlPoints', label: 'Control points (layout x,y; …)', type: 'text',
  get: (e) => (e.layout?.controlPoints ?? []).map((c) => `${c.x},${c.y}`).join('; '),
  set: (e, v) => setIn(e, ['layout', 'controlPoints'], parseCouples(v)),
  check: (v) => (parseCouples(v) ? null : 'must be pairs "x,y" separated by ";"'),
};

function parseCouples(text) {
  if (text.trim() === '') return [];
  const couples = text.split(';').map((pair) => pair.split(',').map((n) => Number(n.trim())));
  return couples.every((c) => c.length === 2 && c.every(Number.isInteger)) ? couples.map(([x, y]) => ({ x, y })) : null;
}

/** @type {Field} */
const connectionType = {
  key: 'layout.connectionType', label: 'Connection type', type: 'select', options: () => CONNECTION_TYPES,
  get: (e) => e.layout?.connectionType ?? 'DIRECT', set: (e, v, model) => withConnectionType(model, e, v),
};

/** @type {Record<string, Field[]>} */
export const FIELDS = {
  point: [
    number('position.x', 'x (mm)'), number('position.y', 'y (mm)'), number('position.z', 'z (mm)'),
    choice('type', 'Type', () => ['HALT_POSITION', 'PARK_POSITION']), orientation, layer,
  ],
  path: [
    { key: 'srcPointName', label: 'From', type: 'text', readOnly: true, get: (e) => e.srcPointName },
    { key: 'destPointName', label: 'To', type: 'text', readOnly: true, get: (e) => e.destPointName },
    number('length', 'Length (mm)', atLeast(1)), number('maxVelocity', 'Max. velocity (mm/s, 0: not forward)', atLeast(0)),
    number('maxReverseVelocity', 'Max. reverse velocity (mm/s, 0: not backward)', atLeast(0)),
    { key: 'locked', label: 'Locked', type: 'checkbox', get: (e) => e.locked, set: (e, v) => ({ ...e, locked: v }) },
    connectionType, controlPoints, layer,
  ],
  location: [
    choice('typeName', 'Type', (model) => model.locationTypes.map((t) => t.name)),
    number('position.x', 'x (mm)'), number('position.y', 'y (mm)'),
    { key: 'locked', label: 'Locked', type: 'checkbox', get: (e) => e.locked, set: (e, v) => ({ ...e, locked: v }) },
    choice('layout.locationRepresentation', 'Symbol', () => REPRESENTATIONS), layer,
  ],
  locationType: [
    list('allowedOperations', 'Allowed operations'), list('allowedPeripheralOperations', 'Peripheral operations'),
    choice('layout.locationRepresentation', 'Symbol', () => REPRESENTATIONS),
  ],
  block: [
    choice('type', 'Type', () => ['SINGLE_VEHICLE_ONLY', 'SAME_DIRECTION_ONLY']),
    { key: 'color', label: 'Colour', type: 'color', get: (e) => e.layout?.color ?? '#FF0000', set: (e, v) => setIn(e, ['layout', 'color'], v.toUpperCase()) },
    list('memberNames', 'Members'),
  ],
  vehicle: [
    number('length', 'Length (mm)', atLeast(1)), number('maxVelocity', 'Max. velocity (mm/s)', atLeast(0)),
    number('maxReverseVelocity', 'Max. reverse velocity (mm/s)', atLeast(0)),
    number('energyLevelCritical', 'Energy critical (%)', percent), number('energyLevelGood', 'Energy good (%)', percent),
    number('energyLevelSufficientlyRecharged', 'Sufficiently recharged (%)', percent),
    number('energyLevelFullyRecharged', 'Fully recharged (%)', percent),
    { key: 'envelopeKey', label: 'Envelope key', type: 'text', get: (e) => e.envelopeKey ?? '', set: (e, v) => ({ ...e, envelopeKey: v.trim() || null }) },
    { key: 'routeColor', label: 'Route colour', type: 'color', get: (e) => e.layout?.routeColor ?? '#00FF00', set: (e, v) => setIn(e, ['layout', 'routeColor'], v.toUpperCase()) },
  ],
};

/** Checks a new name: not empty, not another element's. */
export function nameProblem(name, current, model) {
  if (name.trim() === '') return 'must not be empty';
  if (name === current) return null;
  const taken = Object.values(LISTS).some((list) => model[list].some((e) => e.name === name));
  return taken ? `another element is named "${name}"` : null;
}
