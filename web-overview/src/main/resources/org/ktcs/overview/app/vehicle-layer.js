// The live part of the plant: vehicles moving smoothly between reports, their route ahead and the resources they
// hold (allocated: solid) and have claimed (dashed).

import { onDrawnPath } from './drawn-position.js';

const MIN_BODY_PX = { length: 16, width: 10 };
const MAX_GLIDE_MS = 1500;

export class VehicleLayer {
  constructor(plant) {
    this.plant = plant;
    this.geometry = null;
    this.vehicles = new Map();
    this.orders = new Map();
    this.tracks = new Map();
    this.drawn = new Map();
    // What the last frame drew as held resources and routes ahead, by name (for diagnostics and tests).
    this.drawnResources = new Set();
    this.drawnRoutes = new Set();
    this.labelBoxes = [];
  }

  /** Takes a (possibly different) model's geometry: every vehicle is placed afresh, not glided from old points. */
  setGeometry(geometry) {
    this.geometry = geometry;
    this.tracks.clear();
    this.setVehicles([...this.vehicles.values()]);
  }

  setOrders(orders) {
    this.orders = orders;
    this.plant.requestFrame();
  }

  /** Takes the vehicles' latest state; a vehicle that moved glides from where it is drawn to where it is now. */
  setVehicles(vehicles) {
    const now = performance.now();
    for (const vehicle of vehicles) {
      const target = this.positionOf(vehicle);
      const track = this.tracks.get(vehicle.name);
      if (!target) {
        this.tracks.delete(vehicle.name);
      } else if (!track) {
        this.tracks.set(vehicle.name, { from: target, to: target, start: now, duration: 0, reported: now });
      } else if (target.x !== track.to.x || target.y !== track.to.y || target.angle !== track.to.angle) {
        const from = interpolate(track, now);
        const angle = Number.isFinite(target.angle) ? target.angle : headingOf(from, target, from.angle);
        const duration = Math.min(MAX_GLIDE_MS, Math.max(100, now - track.reported));
        this.tracks.set(vehicle.name, { from, to: { ...target, angle }, start: now, duration, reported: now });
      }
    }
    const names = new Set(vehicles.map((v) => v.name));
    for (const name of this.tracks.keys()) if (!names.has(name)) this.tracks.delete(name);
    this.vehicles = new Map(vehicles.map((v) => [v.name, v]));
    this.plant.requestFrame();
  }

  positionOf(vehicle) {
    const angle = typeof vehicle.pose?.orientationAngle === 'number' ? vehicle.pose.orientationAngle : NaN;
    const precise = vehicle.pose?.position;
    if (precise) {
      const drawn = this.geometry && onDrawnPath(this.geometry, vehicle.allocatedResources, precise, angle);
      return drawn ?? { x: precise.x, y: precise.y, angle };
    }
    const point = vehicle.currentPosition && this.geometry?.points.get(vehicle.currentPosition);
    return point ? { x: point.x, y: point.y, angle } : null;
  }

  /** Draws every vehicle; answers whether one is still gliding (so another frame is needed). */
  draw(ctx, now) {
    let moving = false;
    this.drawn.clear();
    this.drawnResources.clear();
    this.drawnRoutes.clear();
    this.labelBoxes = [];
    for (const vehicle of this.vehicles.values()) this.drawResources(ctx, vehicle);
    for (const vehicle of this.vehicles.values()) this.drawRouteAhead(ctx, vehicle);
    for (const vehicle of this.vehicles.values()) {
      const track = this.tracks.get(vehicle.name);
      if (!track) continue;
      const pose = interpolate(track, now);
      if (now < track.start + track.duration) moving = true;
      this.drawVehicle(ctx, vehicle, pose);
    }
    return moving;
  }

  drawVehicle(ctx, vehicle, pose) {
    const view = this.plant.view;
    const p = view.toScreen(pose.x, pose.y);
    const style = this.plant.themes.vehicleStyle(vehicle);
    const length = Math.max(MIN_BODY_PX.length, (vehicle.boundingBox?.length ?? 1000) * view.scale);
    const width = Math.max(MIN_BODY_PX.width, (vehicle.boundingBox?.width ?? 1000) * view.scale);
    const angle = Number.isFinite(pose.angle) ? (-pose.angle * Math.PI) / 180 : 0;
    ctx.save();
    ctx.translate(p.x, p.y);
    ctx.rotate(angle);
    ctx.fillStyle = style.fill;
    ctx.strokeStyle = style.stroke;
    ctx.lineWidth = style.lineWidth ?? 2;
    ctx.beginPath();
    ctx.moveTo(length / 2 + 4, 0);
    ctx.lineTo(length / 2, -width / 2);
    ctx.lineTo(-length / 2, -width / 2);
    ctx.lineTo(-length / 2, width / 2);
    ctx.lineTo(length / 2, width / 2);
    ctx.closePath();
    ctx.fill();
    ctx.stroke();
    if ((vehicle.loadHandlingDevices ?? []).some((device) => device.full)) {
      ctx.fillStyle = style.stroke;
      ctx.fillRect(-width / 4, -width / 4, width / 2, width / 2);
    }
    ctx.restore();
    this.drawEnergy(ctx, vehicle, p, length);
    if (style.label) {
      ctx.save();
      ctx.font = 'bold 11px system-ui, sans-serif';
      ctx.textAlign = 'center';
      ctx.textBaseline = 'bottom';
      ctx.lineWidth = 3;
      ctx.strokeStyle = 'rgba(255,255,255,0.85)';
      const y = this.freeLabelY(ctx, style.label, p.x, p.y - length / 2 - 6);
      ctx.strokeText(style.label, p.x, y);
      ctx.fillStyle = style.labelColour ?? '#111';
      ctx.fillText(style.label, p.x, y);
      ctx.restore();
    }
    this.drawn.set(vehicle.name, { x: p.x, y: p.y, radius: Math.max(length, width) / 2 + 4 });
  }

  /**
   * The baseline for a label centred at x that covers no label drawn before it in this frame and no location or point
   * name: vehicles side by side (a queue, a charging row) would otherwise write their names over each other. Moves up
   * one line at a time.
   */
  freeLabelY(ctx, text, x, y) {
    const width = ctx.measureText(text).width + 4;
    const box = (baseline) => ({ minX: x - width / 2, maxX: x + width / 2, minY: baseline - LABEL_HEIGHT, maxY: baseline });
    const overlaps = (a) => this.plant.plantLabelSpace.covers(a) ||
      this.labelBoxes.some((b) => a.minX < b.maxX && b.minX < a.maxX && a.minY < b.maxY && b.minY < a.maxY);
    let baseline = y;
    for (let tries = 0; tries < MAX_LABEL_SHIFTS && overlaps(box(baseline)); tries += 1) baseline -= LABEL_HEIGHT;
    this.labelBoxes.push(box(baseline));
    return baseline;
  }

  drawEnergy(ctx, vehicle, p, length) {
    const level = Math.max(0, Math.min(100, vehicle.energyLevel ?? 0));
    const critical = vehicle.energyLevelThresholdSet?.energyLevelCritical ?? 30;
    const width = Math.max(18, length);
    const top = p.y + length / 2 + 4;
    ctx.fillStyle = 'rgba(0,0,0,0.55)';
    ctx.fillRect(p.x - width / 2, top, width, 4);
    ctx.fillStyle = level <= critical ? '#e53935' : '#43a047';
    ctx.fillRect(p.x - width / 2, top, (width * level) / 100, 4);
  }

  drawResources(ctx, vehicle) {
    const colour = routeColour(vehicle);
    ctx.save();
    ctx.strokeStyle = colour;
    ctx.lineCap = 'round';
    ctx.lineWidth = 6;
    ctx.globalAlpha = 0.55;
    ctx.beginPath();
    this.traceResources(ctx, vehicle.allocatedResources);
    ctx.stroke();
    ctx.lineWidth = 3;
    ctx.globalAlpha = 0.8;
    ctx.setLineDash([4, 5]);
    ctx.beginPath();
    this.traceResources(ctx, vehicle.claimedResources);
    ctx.stroke();
    ctx.restore();
  }

  traceResources(ctx, resourceSets) {
    for (const set of resourceSets ?? []) {
      for (const name of set) {
        const path = this.geometry.pathsByName.get(name);
        if (path) {
          this.drawnResources.add(name);
          this.plant.tracePath(ctx, path);
          continue;
        }
        const point = this.geometry.points.get(name);
        if (point) {
          this.drawnResources.add(name);
          const p = this.plant.view.toScreen(point.x, point.y);
          ctx.moveTo(p.x + 7, p.y);
          ctx.arc(p.x, p.y, 7, 0, 2 * Math.PI);
        }
      }
    }
  }

  /** The paths a vehicle still has to drive for its transport order. */
  routeAhead(vehicle) {
    const order = vehicle.transportOrder && this.orders.get(vehicle.transportOrder);
    if (!order) return [];
    const paths = [];
    order.driveOrders.forEach((driveOrder, index) => {
      if (index < order.currentDriveOrderIndex || !driveOrder.route) return;
      driveOrder.route.steps.forEach((step, stepIndex) => {
        const ahead = index > order.currentDriveOrderIndex || stepIndex > order.currentRouteStepIndex;
        if (ahead && step.path) paths.push(step.path);
      });
    });
    return paths;
  }

  drawRouteAhead(ctx, vehicle) {
    const paths = this.routeAhead(vehicle).map((name) => this.geometry.pathsByName.get(name)).filter(Boolean);
    if (paths.length === 0) return;
    paths.forEach((path) => this.drawnRoutes.add(path.name));
    ctx.save();
    ctx.strokeStyle = routeColour(vehicle);
    ctx.lineWidth = 2;
    ctx.globalAlpha = 0.9;
    ctx.beginPath();
    paths.forEach((path) => this.plant.tracePath(ctx, path));
    ctx.stroke();
    ctx.restore();
  }

  /** Where vehicle [name] is drawn at time [now], in model coordinates; null if it has no position. */
  modelPositionAt(name, now) {
    const track = this.tracks.get(name);
    return track ? interpolate(track, now) : null;
  }

  drawnPosition(name) {
    const drawn = this.drawn.get(name);
    return drawn ? { x: drawn.x, y: drawn.y } : null;
  }

  hit(x, y) {
    let best = null;
    for (const [name, drawn] of this.drawn) {
      const distance = Math.hypot(drawn.x - x, drawn.y - y);
      if (distance <= drawn.radius && (!best || distance < best.distance)) best = { name, distance };
    }
    return best?.name ?? null;
  }
}

const LABEL_HEIGHT = 13;
const MAX_LABEL_SHIFTS = 6;

function interpolate(track, now) {
  const t = track.duration <= 0 ? 1 : Math.min(1, (now - track.start) / track.duration);
  const angle = Number.isFinite(track.to.angle) ? track.to.angle : track.from.angle;
  return { x: track.from.x + (track.to.x - track.from.x) * t, y: track.from.y + (track.to.y - track.from.y) * t, angle };
}

function headingOf(from, to, fallback) {
  if (from.x === to.x && from.y === to.y) return fallback;
  return (Math.atan2(to.y - from.y, to.x - from.x) * 180) / Math.PI;
}

function routeColour(vehicle) {
  const c = vehicle.layout?.routeColor;
  return c ? `rgb(${c.red}, ${c.green}, ${c.blue})` : '#00c853';
}
