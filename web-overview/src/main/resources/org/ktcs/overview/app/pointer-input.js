// Pointer input on the plant view: drag to pan, wheel to zoom, click to select what lies under the pointer. A
// vehicle whose driver panel accepts placement (plant.vehicleDrop) is dragged instead, and dropped onto a point.

import { distanceToLine } from './geometry.js';
import { locationSymbolSize } from './shapes.js';

/** The element [plant] draws under a canvas position: vehicles first, then locations, points, paths. */
export function elementAt(plant, x, y) {
  const vehicle = plant.vehicles.hit(x, y);
  if (vehicle) return { kind: 'vehicle', name: vehicle };
  if (!plant.geometry) return null;
  const model = plant.view.toModel(x, y);
  const tolerance = 8 / plant.view.scale;
  const rect = { minX: model.x - tolerance, maxX: model.x + tolerance, minY: model.y - tolerance, maxY: model.y + tolerance };
  const candidates = [...plant.geometry.index.query(rect)].filter((e) => plant.isVisible(e));
  const locationReach = locationSymbolSize(plant.view.scale) / 2 / plant.view.scale;
  const byDistance = (kind, reach, distance) => candidates.filter((e) => e.kind === kind)
    .map((e) => ({ e, d: distance(e) })).filter(({ d }) => d <= reach).sort((a, b) => a.d - b.d)[0]?.e;
  const pointDistance = (e) => Math.hypot(e.x - model.x, e.y - model.y);
  const found = byDistance('location', Math.max(locationReach, tolerance), pointDistance)
    ?? byDistance('point', tolerance, pointDistance)
    ?? byDistance('path', tolerance * 0.75, (e) => distanceToLine(e.line, model.x, model.y));
  return found ? { kind: found.kind, name: found.name } : null;
}

/** The point drawn nearest to a canvas position, within reach of the pointer, or null. */
function pointAt(plant, x, y) {
  if (!plant.geometry) return null;
  const model = plant.view.toModel(x, y);
  const reach = 14 / plant.view.scale;
  const rect = { minX: model.x - reach, maxX: model.x + reach, minY: model.y - reach, maxY: model.y + reach };
  return [...plant.geometry.index.query(rect)].filter((e) => e.kind === 'point' && plant.isVisible(e))
    .map((e) => ({ name: e.name, d: Math.hypot(e.x - model.x, e.y - model.y) }))
    .filter(({ d }) => d <= reach).sort((a, b) => a.d - b.d)[0]?.name ?? null;
}

function dropVehicle(plant, vehicle, point) {
  plant.showDropTarget(null);
  if (point && plant.vehicleDrop?.vehicle === vehicle) plant.vehicleDrop.drop(point);
}

/** Pans, zooms and selects on [plant]'s overlay canvas. */
export function installPointerInput(plant) {
  const target = plant.overlay;
  let drag = null;
  target.addEventListener('pointerdown', (event) => {
    // In the modelling mode its tool takes every gesture (plant.tool, see modelling/pointer-tool.js).
    if (plant.tool) {
      drag = { tool: plant.tool };
      target.setPointerCapture(event.pointerId);
      plant.tool.pointerDown(event);
      return;
    }
    const vehicle = plant.vehicleDrop?.vehicle;
    const grabbed = vehicle && plant.vehicles.hit(event.offsetX, event.offsetY) === vehicle ? vehicle : null;
    drag = { x: event.offsetX, y: event.offsetY, moved: 0, vehicle: grabbed };
    target.setPointerCapture(event.pointerId);
  });
  target.addEventListener('pointermove', (event) => {
    if (plant.tool) {
      plant.tool.pointerMove(event);
      return;
    }
    if (!drag) return;
    const dx = event.offsetX - drag.x;
    const dy = event.offsetY - drag.y;
    drag.moved += Math.abs(dx) + Math.abs(dy);
    drag.x = event.offsetX;
    drag.y = event.offsetY;
    if (drag.vehicle) {
      if (drag.moved > 4) plant.showDropTarget(drag.vehicle, drag.x, drag.y, pointAt(plant, drag.x, drag.y));
    } else if (drag.moved > 4) {
      plant.userMoved = true;
      plant.stopFollowing();
      plant.view.pan(dx, dy);
      plant.invalidate();
    }
  });
  target.addEventListener('pointerup', (event) => {
    if (drag?.tool) {
      drag = null;
      plant.tool?.pointerUp(event);
      return;
    }
    if (drag && drag.moved <= 4) plant.onSelect(elementAt(plant, event.offsetX, event.offsetY));
    else if (drag?.vehicle) dropVehicle(plant, drag.vehicle, pointAt(plant, event.offsetX, event.offsetY));
    drag = null;
  });
  // A cancelled gesture (touch taken over by the browser, window lost focus) ends the drag without a selection.
  const endDrag = () => {
    if (drag?.vehicle) plant.showDropTarget(null);
    if (drag?.tool) plant.tool?.cancel();
    drag = null;
  };
  target.addEventListener('pointercancel', endDrag);
  target.addEventListener('lostpointercapture', endDrag);
  target.addEventListener('wheel', (event) => {
    event.preventDefault();
    plant.userMoved = true;
    plant.view.zoomAt(Math.exp(-event.deltaY * 0.0015), event.offsetX, event.offsetY);
    plant.invalidate();
  }, { passive: false });
}
