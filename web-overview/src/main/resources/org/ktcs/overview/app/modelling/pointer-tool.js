// The modelling mode's pointer: what a press, a drag and a release do with the current tool. Select: click (shift
// adds/removes), shift-drag a box, drag the selection to move it, drag empty space to pan. Point and location: a
// click places one (snapped to the grid). Path: click a point, then another; from a location to a point it links.

import { elementAt } from '../pointer-input.js';
import { addLink, addLocation, addPath, addPoint, moveElements } from './model-edits.js';
import { drawHandles, handleAt, movedControlPoint, selectedPath } from './control-points.js';

const CLICK_SLOP = 4;

/** @typedef {{kind: string, name: string}} Hit */

export class PointerTool {
  /** @param {import('./editor.js').ModellingMode} editor */
  constructor(editor) {
    this.editor = editor;
    this.gesture = null;
    /** While a path is drawn: its first end (a point or location name with its kind). */
    this.pathStart = null;
    /** The pointer's last position on the canvas (for the rubber band of a path and the box). */
    this.pointer = null;
  }

  get plant() { return this.editor.plant; }

  /** @returns {Hit|null} the point, location or path under a canvas position */
  hit(x, y) {
    const found = elementAt(this.plant, x, y);
    return found && found.kind !== 'vehicle' ? found : null;
  }

  snapped(x, y) {
    const model = this.plant.view.toModel(x, y);
    return this.editor.snap(model.x, model.y);
  }

  pointerDown(event) {
    const [x, y] = [event.offsetX, event.offsetY];
    const hit = this.hit(x, y);
    this.gesture = { startX: x, startY: y, x, y, moved: 0, hit, shift: event.shiftKey, kind: 'pan' };
    if (this.editor.tool !== 'select') return;
    const handle = handleAt(this.editor, x, y);
    if (handle >= 0) {
      Object.assign(this.gesture, { kind: 'control', path: selectedPath(this.editor).name, handle });
    } else if (hit && (hit.kind === 'point' || hit.kind === 'location')) {
      const key = `${hit.kind}:${hit.name}`;
      if (!this.editor.selection.has(key) && !event.shiftKey) this.editor.select([key]);
      if (this.editor.selection.has(key)) this.gesture.kind = 'move';
    } else if (event.shiftKey) {
      this.gesture.kind = 'box';
    }
  }

  pointerMove(event) {
    const [x, y] = [event.offsetX, event.offsetY];
    this.pointer = { x, y };
    const gesture = this.gesture;
    if (!gesture) {
      if (this.pathStart) this.plant.requestFrame();
      return;
    }
    const dx = x - gesture.x;
    const dy = y - gesture.y;
    gesture.moved += Math.abs(dx) + Math.abs(dy);
    gesture.x = x;
    gesture.y = y;
    if (gesture.moved <= CLICK_SLOP) return;
    if (gesture.kind === 'pan') {
      this.plant.userMoved = true;
      this.plant.view.pan(dx, dy);
      this.plant.invalidate();
    } else if (gesture.kind === 'move') {
      this.previewMove(gesture);
    } else if (gesture.kind === 'control') {
      this.editor.preview(movedControlPoint(this.editor, gesture.path, gesture.handle, x, y));
    } else {
      this.plant.requestFrame();
    }
  }

  /**
   * Shows the selection moved without rebuilding the drawing of a large plant on every step: the drawn points and
   * locations move (straight paths and links follow, as they share the points); the drop rebuilds it.
   */
  previewMove(gesture) {
    const plant = this.plant;
    gesture.originals ??= [...this.editor.selection].map((key) => {
      const kind = key.slice(0, key.indexOf(':'));
      return kind === 'point' || kind === 'location' ? plant.elementNamed(kind, key.slice(kind.length + 1)) : null;
    }).filter(Boolean).map((element) => ({ element, x: element.x, y: element.y }));
    const from = this.snapped(gesture.startX, gesture.startY);
    const to = this.snapped(gesture.x, gesture.y);
    for (const { element, x, y } of gesture.originals) {
      element.x = x + to.x - from.x;
      element.y = y + to.y - from.y;
    }
    plant.invalidate();
  }

  movedModel(gesture) {
    const from = this.snapped(gesture.startX, gesture.startY);
    const to = this.snapped(gesture.x, gesture.y);
    return moveElements(this.editor.draft.model, this.editor.selection, to.x - from.x, to.y - from.y);
  }

  pointerUp(event) {
    const gesture = this.gesture;
    this.gesture = null;
    if (!gesture) return;
    const click = gesture.moved <= CLICK_SLOP;
    if (gesture.kind === 'move' && !click) {
      this.editor.edit(this.movedModel(gesture));
    } else if (gesture.kind === 'control' && !click) {
      this.editor.edit(movedControlPoint(this.editor, gesture.path, gesture.handle, gesture.x, gesture.y));
    } else if (gesture.kind === 'box' && !click) {
      this.selectBox(gesture, event.shiftKey);
    } else if (click) {
      this.click(gesture.hit, gesture.startX, gesture.startY, gesture.shift);
    }
    this.plant.requestFrame();
  }

  cancel() {
    for (const { element, x, y } of this.gesture?.originals ?? []) Object.assign(element, { x, y });
    this.gesture = null;
    this.pathStart = null;
    this.editor.preview(null);
    this.plant.requestFrame();
  }

  click(hit, x, y, shift) {
    const editor = this.editor;
    const model = editor.draft.model;
    const layerId = editor.activeLayer;
    if (editor.tool === 'select') {
      if (!hit) editor.select(shift ? [...editor.selection] : []);
      else if (shift) editor.toggle(`${hit.kind}:${hit.name}`);
      else editor.select([`${hit.kind}:${hit.name}`]);
    } else if (editor.tool === 'point') {
      const at = this.snapped(x, y);
      const added = addPoint(model, at.x, at.y, layerId);
      editor.edit(added.model, [`point:${added.name}`]);
    } else if (editor.tool === 'location') {
      const at = this.snapped(x, y);
      const added = addLocation(model, at.x, at.y, null, layerId);
      editor.edit(added.model, [`location:${added.name}`]);
    } else if (editor.tool === 'path') {
      this.pathClick(hit, layerId);
    }
  }

  pathClick(hit, layerId) {
    const editor = this.editor;
    if (!hit || hit.kind === 'path') {
      this.pathStart = null;
      return;
    }
    if (!this.pathStart) {
      this.pathStart = hit;
      editor.select([`${hit.kind}:${hit.name}`]);
      return;
    }
    const start = this.pathStart;
    this.pathStart = null;
    if (start.kind === 'point' && hit.kind === 'point') {
      const added = addPath(editor.draft.model, start.name, hit.name, layerId);
      if (added) editor.edit(added.model, [`path:${added.name}`]);
      else editor.notify(`There is a path from ${start.name} to ${hit.name} already, or both ends are the same point.`);
    } else if (start.kind !== hit.kind) {
      const [location, point] = start.kind === 'location' ? [start.name, hit.name] : [hit.name, start.name];
      editor.edit(addLink(editor.draft.model, location, point), [`location:${location}`]);
    } else {
      editor.notify('A path connects two points; a link connects a location and a point.');
    }
  }

  selectBox(gesture, add) {
    const a = this.plant.view.toModel(gesture.startX, gesture.startY);
    const b = this.plant.view.toModel(gesture.x, gesture.y);
    const rect = { minX: Math.min(a.x, b.x), maxX: Math.max(a.x, b.x), minY: Math.min(a.y, b.y), maxY: Math.max(a.y, b.y) };
    const inside = [...this.plant.geometry.index.query(rect)].filter((e) => this.plant.isVisible(e) && within(e, rect));
    const keys = inside.map((e) => `${e.kind}:${e.name}`);
    this.editor.select(add ? [...this.editor.selection, ...keys] : keys);
  }

  /** Draws the box being dragged and the rubber band of a path being drawn. */
  draw(ctx) {
    drawHandles(ctx, this.editor);
    const gesture = this.gesture;
    ctx.save();
    ctx.strokeStyle = '#ff9800';
    ctx.setLineDash([5, 4]);
    if (gesture?.kind === 'box' && gesture.moved > CLICK_SLOP) {
      ctx.strokeRect(gesture.startX, gesture.startY, gesture.x - gesture.startX, gesture.y - gesture.startY);
    }
    if (this.pathStart && this.pointer) {
      const element = this.plant.elementNamed(this.pathStart.kind, this.pathStart.name);
      if (element) {
        const from = this.plant.view.toScreen(element.x, element.y);
        ctx.beginPath();
        ctx.moveTo(from.x, from.y);
        ctx.lineTo(this.pointer.x, this.pointer.y);
        ctx.stroke();
      }
    }
    ctx.restore();
  }
}

function within(element, rect) {
  const b = element.bounds ?? { minX: element.x, maxX: element.x, minY: element.y, maxY: element.y };
  return b.minX >= rect.minX && b.maxX <= rect.maxX && b.minY >= rect.minY && b.maxY <= rect.maxY;
}
