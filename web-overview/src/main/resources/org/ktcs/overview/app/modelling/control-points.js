// A path's control points (openTCS keeps them in layout coordinates: model mm divided by the layout's scale, y
// pointing down): where they are drawn, defaults for a new connection type, and moving one by dragging its handle.

import { replaceNamed } from './model-edits.js';
import { controlsFit, defaultControlFractions } from '../path-shapes.js';

const HANDLE_REACH_PX = 9;

/** The layout's scale (mm per layout unit). */
function scaleOf(model) {
  return { x: model.visualLayout?.scaleX ?? 50, y: model.visualLayout?.scaleY ?? 50 };
}

/** Control point [c] in model mm. */
export function toModel(model, c) {
  const scale = scaleOf(model);
  return { x: c.x * scale.x, y: -c.y * scale.y };
}

/** Model mm [p] as a control point. */
export function toLayout(model, p) {
  const scale = scaleOf(model);
  return { x: Math.round(p.x / scale.x), y: Math.round(-p.y / scale.y) };
}

/**
 * [path] with the connection type [type]. Control points that do not fit the type are replaced by the ones openTCS's
 * Model Editor gives a new curve, placed along the straight line: BEZIER two (at a third and two thirds), BEZIER_3
 * five (at every sixth), POLYPATH one (in the middle); DIRECT, ELBOW and SLANTED use none.
 */
export function withConnectionType(model, path, type) {
  const layout = { ...path.layout, connectionType: type };
  if (!controlsFit(type, layout.controlPoints?.length ?? 0)) {
    const src = model.points.find((p) => p.name === path.srcPointName)?.position;
    const dst = model.points.find((p) => p.name === path.destPointName)?.position;
    const fractions = src && dst ? defaultControlFractions(type) : [];
    layout.controlPoints = fractions.map((t) => toLayout(model, { x: src.x + (dst.x - src.x) * t, y: src.y + (dst.y - src.y) * t }));
  }
  return { ...path, layout };
}

/** The only selected path, if exactly one path is selected. */
export function selectedPath(editor) {
  if (editor.selection.size !== 1) return null;
  const [key] = editor.selection;
  if (!key.startsWith('path:')) return null;
  return editor.draft.model.paths.find((p) => p.name === key.slice(5)) ?? null;
}

/** The index of the selected path's control point whose handle is under canvas position (x, y), or -1. */
export function handleAt(editor, x, y) {
  const path = selectedPath(editor);
  if (!path) return -1;
  const model = editor.draft.model;
  return (path.layout?.controlPoints ?? []).findIndex((c) => {
    const m = toModel(model, c);
    const s = editor.plant.view.toScreen(m.x, m.y);
    return Math.hypot(s.x - x, s.y - y) <= HANDLE_REACH_PX;
  });
}

/** The model with control point [index] of [pathName] moved to canvas position (x, y), snapped to the grid. */
export function movedControlPoint(editor, pathName, index, x, y) {
  const model = editor.draft.model;
  const at = editor.plant.view.toModel(x, y);
  const snapped = editor.snap(at.x, at.y);
  return replaceNamed(model, 'path', pathName, (p) => ({
    ...p,
    layout: { ...p.layout, controlPoints: p.layout.controlPoints.map((c, i) => (i === index ? toLayout(model, snapped) : c)) },
  }));
}

/** Draws the handles of the selected path's control points (squares joined by thin lines to the path's ends). */
export function drawHandles(ctx, editor) {
  const path = selectedPath(editor);
  if (!path || !(path.layout?.controlPoints?.length)) return;
  const model = editor.draft.model;
  const view = editor.plant.view;
  const ends = [path.srcPointName, path.destPointName].map((n) => model.points.find((p) => p.name === n)?.position);
  const handles = path.layout.controlPoints.map((c) => toModel(model, c));
  const line = [ends[0], ...handles, ends[1]].filter(Boolean).map((p) => view.toScreen(p.x, p.y));
  ctx.save();
  ctx.strokeStyle = '#ff9800';
  ctx.lineWidth = 1;
  ctx.setLineDash([2, 3]);
  ctx.beginPath();
  line.forEach((p, i) => (i === 0 ? ctx.moveTo(p.x, p.y) : ctx.lineTo(p.x, p.y)));
  ctx.stroke();
  ctx.setLineDash([]);
  ctx.fillStyle = '#fff';
  for (const h of handles) {
    const s = view.toScreen(h.x, h.y);
    ctx.fillRect(s.x - 4, s.y - 4, 8, 8);
    ctx.strokeRect(s.x - 4, s.y - 4, 8, 8);
  }
  ctx.restore();
}
