// Draws the plant on two stacked canvases: the static plant (redrawn when the view or the model changes) and a
// live overlay (vehicles, routes, resources, selection; redrawn while something moves). Only what lies in view is
// drawn, found through the geometry's grid index, so a plant of 10,000 points stays smooth.

import { buildGeometry, midpointOf } from './geometry.js';
import { ViewTransform } from './view-transform.js';
import { VehicleLayer } from './vehicle-layer.js';
import { installPointerInput } from './pointer-input.js';
import { LabelSpace } from './label-space.js';
import { COLOURS, StaticLayer } from './static-layer.js';

export class PlantView {
  constructor(canvas, { themes, onSelect }) {
    this.canvas = canvas;
    this.overlay = document.createElement('canvas');
    this.overlay.className = 'plant-overlay';
    canvas.after(this.overlay);
    this.themes = themes;
    this.onSelect = onSelect;
    /** @type {((vehicle: string | null) => void) | undefined} Told which vehicle the view follows, if any. */
    this.onFollowChange = undefined;
    /** @type {any} The modelling mode's tool while it draws the plant (pointer input and overlay go to it). */
    this.tool = null;
    this.view = new ViewTransform();
    this.geometry = null;
    this.hiddenLayers = new Set();
    /** The boxes of the location and point names drawn last (names that would cover another are left out). */
    this.plantLabels = [];
    this.plantLabelSpace = new LabelSpace();
    this.showLabels = true;
    this.selection = null;
    this.highlightedRoute = [];
    this.lastDrawn = { points: 0, paths: 0, locations: 0, staticMs: 0 };
    this.staticLayer = new StaticLayer(this);
    this.vehicles = new VehicleLayer(this);
    this.staticDirty = true;
    this.frameRequested = false;
    installPointerInput(this);
    new ResizeObserver(() => this.resize()).observe(canvas.parentElement);
    this.resize();
  }

  setModel(model) {
    const first = this.geometry === null;
    this.geometry = buildGeometry(model);
    this.vehicles.setGeometry(this.geometry);
    if (first) this.fit();
    this.invalidate();
  }

  /** A path or location changed (a lock); the rest of the model stays. */
  updateElement(changed) {
    const geometry = this.geometry;
    if (!geometry || !changed) return;
    const element = geometry.pathsByName.get(changed.name) ?? geometry.locationsByName.get(changed.name);
    if (!element) return;
    element.locked = changed.locked;
    if (element.kind === 'location') element.dto = changed;
    this.invalidate();
  }

  fit() {
    if (!this.geometry) return;
    this.view.fit(this.geometry.bounds, this.width, this.height);
    this.invalidate();
  }

  zoom(factor) {
    this.view.zoomAt(factor, this.width / 2, this.height / 2);
    this.invalidate();
  }

  setLayerVisible(layerId, visible) {
    if (visible) this.hiddenLayers.delete(layerId);
    else this.hiddenLayers.add(layerId);
    this.invalidate();
  }

  setLabels(show) {
    this.showLabels = show;
    this.invalidate();
  }

  /** Marks an element (or null) as selected. */
  select(selection) {
    this.selection = selection;
    this.requestFrame();
  }

  /** Highlights a route: a list of path names (e.g. of a selected order). */
  highlightRoute(pathNames) {
    this.highlightedRoute = pathNames;
    this.requestFrame();
  }

  invalidate() {
    this.staticDirty = true;
    this.requestFrame();
  }

  requestFrame() {
    if (this.frameRequested) return;
    this.frameRequested = true;
    requestAnimationFrame((now) => {
      this.frameRequested = false;
      this.drawFrame(now);
    });
  }

  /**
   * Centres the view on vehicle [name] ("find"); with [follow] it stays centred while the vehicle moves, until the
   * operator pans. Answers whether the vehicle is drawn at all (it is not without a position).
   */
  centreOnVehicle(name, follow = false) {
    const pose = this.vehicles.modelPositionAt(name, performance.now());
    this.following = follow && pose ? name : null;
    this.onFollowChange?.(this.following);
    if (!pose) return false;
    this.userMoved = true;
    this.view.centreOn(pose.x, pose.y, this.width, this.height);
    this.invalidate();
    return true;
  }

  /** The operator panned: following a vehicle ends. */
  stopFollowing() {
    if (!this.following) return;
    this.following = null;
    this.onFollowChange?.(null);
  }

  keepFollowing(now) {
    const pose = this.following && this.vehicles.modelPositionAt(this.following, now);
    if (!pose) return;
    const before = this.view.toScreen(pose.x, pose.y);
    if (Math.abs(before.x - this.width / 2) < 0.5 && Math.abs(before.y - this.height / 2) < 0.5) return;
    this.view.centreOn(pose.x, pose.y, this.width, this.height);
    this.staticDirty = true;
  }

  drawFrame(now) {
    this.keepFollowing(now);
    if (this.staticDirty) {
      this.drawStatic();
      this.staticDirty = false;
    }
    const moving = this.drawOverlay(now);
    if (moving) this.requestFrame();
  }

  resize() {
    const box = this.canvas.parentElement.getBoundingClientRect();
    const ratio = window.devicePixelRatio || 1;
    this.width = Math.max(1, box.width);
    this.height = Math.max(1, box.height);
    for (const canvas of [this.canvas, this.overlay]) {
      canvas.width = Math.round(this.width * ratio);
      canvas.height = Math.round(this.height * ratio);
      canvas.style.width = `${this.width}px`;
      canvas.style.height = `${this.height}px`;
      canvas.getContext('2d').setTransform(ratio, 0, 0, ratio, 0, 0);
    }
    if (this.geometry && !this.userMoved) this.view.fit(this.geometry.bounds, this.width, this.height);
    this.invalidate();
  }

  isVisible(element) {
    return !this.hiddenLayers.has(element.layerId);
  }

  /** What lies in the canvas (plus a margin), on visible layers. */
  elementsInView() {
    const margin = 40 / this.view.scale;
    const rect = this.view.visibleRect(this.width, this.height);
    const padded = { minX: rect.minX - margin, maxX: rect.maxX + margin, minY: rect.minY - margin, maxY: rect.maxY + margin };
    const found = { points: [], paths: [], locations: [] };
    for (const element of this.geometry.index.query(padded)) {
      if (!this.isVisible(element) || !intersects(element, padded)) continue;
      found[`${element.kind}s`].push(element);
    }
    return found;
  }

  drawStatic() {
    const started = performance.now();
    const ctx = this.canvas.getContext('2d');
    ctx.fillStyle = COLOURS.background;
    ctx.fillRect(0, 0, this.width, this.height);
    if (!this.geometry) return;
    const inView = this.elementsInView();
    this.staticLayer.draw(ctx, inView);
    this.lastDrawn = {
      points: inView.points.length,
      paths: inView.paths.length,
      locations: inView.locations.length,
      staticMs: performance.now() - started,
    };
  }

  /** Traces [path]'s line (in screen coordinates) onto [ctx]'s current path. */
  tracePath(ctx, path) {
    this.staticLayer.tracePath(ctx, path);
  }

  drawOverlay(now) {
    const ctx = this.overlay.getContext('2d');
    ctx.clearRect(0, 0, this.width, this.height);
    if (!this.geometry) return false;
    // The modelling mode draws the model being edited, without the live vehicles.
    if (this.tool) {
      this.tool.drawOverlay(ctx);
      return false;
    }
    this.drawHighlightedRoute(ctx);
    const moving = this.vehicles.draw(ctx, now);
    this.drawSelection(ctx);
    if (this.dropTarget) drawDropTarget(ctx, this.dropTarget, this);
    return moving;
  }

  /** While a vehicle is dragged: where the pointer is and the point it would land on (null ends it). */
  showDropTarget(vehicle, x, y, point) {
    this.dropTarget = vehicle ? { vehicle, x, y, point } : null;
    this.requestFrame();
  }

  drawHighlightedRoute(ctx) {
    if (this.highlightedRoute.length === 0) return;
    ctx.save();
    ctx.strokeStyle = COLOURS.selection;
    ctx.globalAlpha = 0.7;
    ctx.lineWidth = 7;
    ctx.lineCap = 'round';
    ctx.beginPath();
    for (const name of this.highlightedRoute) {
      const path = this.geometry.pathsByName.get(name);
      if (path) this.tracePath(ctx, path);
    }
    ctx.stroke();
    ctx.restore();
  }

  drawSelection(ctx) {
    const selected = this.selection;
    if (!selected || selected.kind === 'vehicle') return;
    const element = this.elementNamed(selected.kind, selected.name);
    if (!element) return;
    ctx.save();
    ctx.strokeStyle = COLOURS.selection;
    ctx.lineWidth = 3;
    ctx.beginPath();
    if (element.kind === 'path') {
      this.tracePath(ctx, element);
    } else {
      const p = this.view.toScreen(element.x, element.y);
      ctx.arc(p.x, p.y, 14, 0, 2 * Math.PI);
    }
    ctx.stroke();
    ctx.restore();
  }

  elementNamed(kind, name) {
    const geometry = this.geometry;
    if (!geometry) return null;
    if (kind === 'point') return geometry.points.get(name);
    if (kind === 'path') return geometry.pathsByName.get(name);
    if (kind === 'location') return geometry.locationsByName.get(name);
    return null;
  }

  /** Where an element is drawn, in page coordinates (its middle for a path). */
  pagePositionOf(kind, name) {
    const box = this.canvas.getBoundingClientRect();
    let screen;
    if (kind === 'vehicle') {
      screen = this.vehicles.drawnPosition(name);
    } else {
      const element = this.elementNamed(kind, name);
      if (!element) return null;
      const model = kind === 'path' ? midpointOf(element) : element;
      screen = this.view.toScreen(model.x, model.y);
    }
    return screen ? { x: box.left + screen.x, y: box.top + screen.y } : null;
  }


}

function drawDropTarget(ctx, { vehicle, x, y, point }, plant) {
  ctx.save();
  ctx.strokeStyle = COLOURS.selection;
  ctx.fillStyle = COLOURS.selection;
  ctx.lineWidth = 3;
  const target = point ? plant.geometry.points.get(point) : null;
  if (target) {
    const p = plant.view.toScreen(target.x, target.y);
    ctx.beginPath();
    ctx.arc(p.x, p.y, 16, 0, 2 * Math.PI);
    ctx.stroke();
  }
  ctx.globalAlpha = 0.6;
  ctx.beginPath();
  ctx.arc(x, y, 9, 0, 2 * Math.PI);
  ctx.fill();
  ctx.globalAlpha = 1;
  ctx.font = '12px sans-serif';
  ctx.fillText(point ? `${vehicle} → ${point}` : vehicle, x + 12, y - 12);
  ctx.restore();
}

function intersects(element, rect) {
  const b = element.bounds;
  if (!b) return element.x >= rect.minX && element.x <= rect.maxX && element.y >= rect.minY && element.y <= rect.maxY;
  return b.maxX >= rect.minX && b.minX <= rect.maxX && b.maxY >= rect.minY && b.minY <= rect.maxY;
}
