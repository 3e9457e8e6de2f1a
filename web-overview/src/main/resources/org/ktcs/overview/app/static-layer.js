// The static plant: blocks, paths with their direction arrows, location links, points, locations and their names.
// Drawn onto the lower canvas only when the view or the model changes; [PlantView] decides when.

import { midpointOf } from './geometry.js';
import { clamp, drawCross, drawSymbol, locationSymbolSize, traceArrow } from './shapes.js';
import { LabelSpace, textBox } from './label-space.js';

export const COLOURS = {
  background: '#f6f7f9',
  path: '#7d8a9a',
  locked: '#d0342c',
  arrow: '#56606d',
  link: '#9aa5b1',
  halt: '#4a5968',
  park: '#1f78b4',
  label: '#222a33',
  selection: '#ff9800',
};
const ARROW_MIN_SCREEN_LENGTH = 28;
const MAX_LABELS = 600;
const POINT_SIZE_MM = 450;

export class StaticLayer {
  /** @param {any} plant the [PlantView] whose view, geometry and themes this layer draws with */
  constructor(plant) {
    this.plant = plant;
  }

  /** Draws what lies in view ([inView] as answered by `PlantView.elementsInView`). */
  draw(ctx, inView) {
    this.drawBlocks(ctx, inView);
    this.drawPaths(ctx, inView.paths);
    this.drawLinks(ctx, inView.locations);
    this.drawPoints(ctx, inView.points);
    this.drawLocations(ctx, inView.locations);
    this.plant.plantLabels = [];
    this.plant.plantLabelSpace = new LabelSpace();
    if (this.plant.showLabels) this.drawLabels(ctx, inView);
  }

  drawBlocks(ctx, inView) {
    const byColour = new Map();
    for (const element of [...inView.paths, ...inView.points]) {
      const colour = this.plant.geometry.blockColours.get(element.name);
      if (!colour) continue;
      if (!byColour.has(colour)) byColour.set(colour, []);
      byColour.get(colour).push(element);
    }
    ctx.save();
    ctx.globalAlpha = 0.28;
    ctx.lineCap = 'round';
    for (const [colour, elements] of byColour) {
      ctx.strokeStyle = colour;
      ctx.fillStyle = colour;
      ctx.lineWidth = 9;
      ctx.beginPath();
      for (const element of elements) {
        if (element.kind === 'path') this.tracePath(ctx, element);
      }
      ctx.stroke();
      ctx.beginPath();
      for (const element of elements) {
        if (element.kind !== 'point') continue;
        const p = this.plant.view.toScreen(element.x, element.y);
        ctx.moveTo(p.x + 8, p.y);
        ctx.arc(p.x, p.y, 8, 0, 2 * Math.PI);
      }
      ctx.fill();
    }
    ctx.restore();
  }

  tracePath(ctx, path) {
    const first = this.plant.view.toScreen(path.line[0].x, path.line[0].y);
    ctx.moveTo(first.x, first.y);
    for (let i = 1; i < path.line.length; i += 1) {
      const p = this.plant.view.toScreen(path.line[i].x, path.line[i].y);
      ctx.lineTo(p.x, p.y);
    }
  }

  drawPaths(ctx, paths) {
    ctx.lineWidth = 1.5;
    ctx.strokeStyle = COLOURS.path;
    ctx.beginPath();
    paths.filter((p) => !p.locked).forEach((p) => this.tracePath(ctx, p));
    ctx.stroke();
    ctx.save();
    ctx.strokeStyle = COLOURS.locked;
    ctx.lineWidth = 2.5;
    ctx.setLineDash([6, 4]);
    ctx.beginPath();
    paths.filter((p) => p.locked).forEach((p) => this.tracePath(ctx, p));
    ctx.stroke();
    ctx.restore();
    this.drawArrows(ctx, paths);
  }

  drawArrows(ctx, paths) {
    ctx.fillStyle = COLOURS.arrow;
    ctx.beginPath();
    for (const path of paths) {
      const a = this.plant.view.toScreen(path.src.x, path.src.y);
      const b = this.plant.view.toScreen(path.dst.x, path.dst.y);
      if (Math.hypot(b.x - a.x, b.y - a.y) < ARROW_MIN_SCREEN_LENGTH) continue;
      const middle = midpointOf(path);
      const m = this.plant.view.toScreen(middle.x, middle.y);
      const angle = -middle.angle;
      if (path.forward) traceArrow(ctx, m.x, m.y, angle);
      if (path.reverse) traceArrow(ctx, m.x, m.y, angle + Math.PI);
    }
    ctx.fill();
  }

  drawLinks(ctx, locations) {
    ctx.save();
    ctx.strokeStyle = COLOURS.link;
    ctx.lineWidth = 1;
    ctx.setLineDash([3, 3]);
    ctx.beginPath();
    for (const location of locations) {
      const from = this.plant.view.toScreen(location.x, location.y);
      for (const point of location.links) {
        const to = this.plant.view.toScreen(point.x, point.y);
        ctx.moveTo(from.x, from.y);
        ctx.lineTo(to.x, to.y);
      }
    }
    ctx.stroke();
    ctx.restore();
  }

  drawPoints(ctx, points) {
    const size = clamp(POINT_SIZE_MM * this.plant.view.scale, 2.5, 12);
    for (const [type, colour] of [['HALT_POSITION', COLOURS.halt], ['PARK_POSITION', COLOURS.park]]) {
      ctx.fillStyle = colour;
      ctx.beginPath();
      for (const point of points) {
        if ((point.type === 'PARK_POSITION') !== (type === 'PARK_POSITION')) continue;
        const p = this.plant.view.toScreen(point.x, point.y);
        if (type === 'PARK_POSITION') {
          ctx.moveTo(p.x + size * 0.7, p.y);
          ctx.arc(p.x, p.y, size * 0.7, 0, 2 * Math.PI);
        } else {
          ctx.rect(p.x - size / 2, p.y - size / 2, size, size);
        }
      }
      ctx.fill();
    }
  }

  drawLocations(ctx, locations) {
    const size = locationSymbolSize(this.plant.view.scale);
    for (const location of locations) {
      const style = this.plant.themes.locationStyle(location.dto, this.plant.geometry.locationTypes.get(location.typeName));
      const p = this.plant.view.toScreen(location.x, location.y);
      drawSymbol(ctx, style, p.x, p.y, size);
      if (location.locked) drawCross(ctx, p.x, p.y, size * 0.7, COLOURS.locked);
    }
  }

  drawLabels(ctx, inView) {
    ctx.font = '11px system-ui, sans-serif';
    ctx.fillStyle = COLOURS.label;
    ctx.textAlign = 'center';
    ctx.textBaseline = 'top';
    const locationSize = locationSymbolSize(this.plant.view.scale);
    const labels = new LabelSpace();
    this.plant.plantLabels = labels.boxes;
    this.plant.plantLabelSpace = labels;
    // Location names crowd each other on a zoomed-out large plant; a small plant always shows them.
    if (inView.locations.length <= 40 || locationSize >= 12) {
      for (const location of inView.locations) {
        const p = this.plant.view.toScreen(location.x, location.y);
        const top = p.y + locationSize / 2 + 3;
        if (labels.tryPlace(textBox(ctx, location.name, p.x, top, 13))) ctx.fillText(location.name, p.x, top);
      }
    }
    // Point names only once they no longer crowd each other; while modelling a small plant, always (names are what
    // the user refers to; one that would cover another is still left out).
    const modellingSmall = Boolean(this.plant.tool) && inView.points.length <= 60;
    if (inView.points.length <= MAX_LABELS && (this.plant.view.scale * 1500 > 40 || modellingSmall)) {
      ctx.fillStyle = '#5f6b78';
      ctx.font = '10px system-ui, sans-serif';
      for (const point of inView.points) {
        const p = this.plant.view.toScreen(point.x, point.y);
        if (labels.tryPlace(textBox(ctx, point.name, p.x, p.y + 7, 12))) ctx.fillText(point.name, p.x, p.y + 7);
      }
    }
  }
}
