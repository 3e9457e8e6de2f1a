// Copy and paste: copies of the copied elements, named afresh by openTCS's naming schemes ("Point-0009",
// "Vehicle-0002", "LType-0003", "Block-0002"; a path after its new ends), and the references between copies made to
// point at the copies: a path between two copied points, a link to a copied point, a copied location of a copied
// type, a copied block's copied members.

import { addBlock, addLocation, addLocationType, addPath, addPoint, addVehicle, replaceNamed } from './model-edits.js';

/**
 * Copies of the elements of [source] whose "kind:name" keys are in [keys], added to [model]; points and locations
 * are moved by (dx, dy) mm. Paths between copied points are copied with them. Answers the model and the copies' keys.
 * @param {import('./model-edits.js').ModelJson} model
 * @param {import('./model-edits.js').ModelJson} source
 * @param {Set<string>} keys
 * @param {number} dx
 * @param {number} dy
 * @returns {{model: import('./model-edits.js').ModelJson, keys: Set<string>}}
 */
export function pasteCopies(model, source, keys, dx, dy) {
  const copying = (kind) => (e) => keys.has(`${kind}:${e.name}`);
  const state = { model, renamed: new Map(), added: new Set() };
  /** Adds an element made by [create], then gives it [original]'s fields but for its name and [overrides]. */
  const copy = (kind, original, create, overrides) => {
    const created = create(state.model);
    if (!created) return;
    state.model = replaceNamed(created.model, kind, created.name, (e) => ({ ...original, ...overrides(e), name: e.name }));
    state.renamed.set(original.name, created.name);
    state.added.add(`${kind}:${created.name}`);
  };
  const as = (name) => state.renamed.get(name) ?? name;
  for (const type of source.locationTypes.filter(copying('locationType'))) {
    copy('locationType', type, addLocationType, () => ({}));
  }
  for (const point of source.points.filter(copying('point'))) {
    const at = { x: point.position.x + dx, y: point.position.y + dy };
    copy('point', point, (m) => addPoint(m, at.x, at.y), (p) => ({ position: p.position }));
  }
  for (const path of source.paths) {
    const [src, dst] = [state.renamed.get(path.srcPointName), state.renamed.get(path.destPointName)];
    if (!src || !dst) continue;
    copy('path', path, (m) => addPath(m, src, dst), () => ({ srcPointName: src, destPointName: dst }));
  }
  for (const location of source.locations.filter(copying('location'))) {
    const at = { x: location.position.x + dx, y: location.position.y + dy };
    const links = location.links.filter((k) => state.renamed.has(k.pointName)).map((k) => ({ ...k, pointName: as(k.pointName) }));
    copy('location', location, (m) => addLocation(m, at.x, at.y), (l) => ({ position: l.position, links, typeName: as(location.typeName) }));
  }
  for (const vehicle of source.vehicles.filter(copying('vehicle'))) copy('vehicle', vehicle, addVehicle, () => ({}));
  for (const block of source.blocks.filter(copying('block'))) {
    copy('block', block, (m) => addBlock(m), () => ({ memberNames: block.memberNames.map(as) }));
  }
  return { model: state.model, keys: state.added };
}
