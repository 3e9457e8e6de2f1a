// Canvas shape primitives shared by the plant view's layers: arrow heads, location symbols, crosses.

const LOCATION_SIZE_MM = 1200;

/** The on-screen size in pixels of a location symbol at [scale] pixels per millimetre. */
export function locationSymbolSize(scale) {
  return clamp(LOCATION_SIZE_MM * scale, 8, 30);
}

/** Adds an arrow head pointing along [angle] at (x, y) to the current path. */
export function traceArrow(ctx, x, y, angle) {
  const size = 6;
  const cos = Math.cos(angle);
  const sin = Math.sin(angle);
  ctx.moveTo(x + cos * size, y + sin * size);
  ctx.lineTo(x - cos * size - sin * size * 0.7, y - sin * size + cos * size * 0.7);
  ctx.lineTo(x - cos * size + sin * size * 0.7, y - sin * size - cos * size * 0.7);
  ctx.closePath();
}

/** Draws a location symbol of a theme style: a shape name or a single character. */
export function drawSymbol(ctx, style, x, y, size) {
  const half = size / 2;
  ctx.save();
  ctx.fillStyle = style.fill;
  ctx.strokeStyle = style.stroke;
  ctx.lineWidth = style.lineWidth ?? 1.5;
  ctx.beginPath();
  switch (style.symbol) {
    case 'none':
      ctx.restore();
      return;
    case 'circle':
      ctx.arc(x, y, half, 0, 2 * Math.PI);
      break;
    case 'triangle':
      ctx.moveTo(x, y - half);
      ctx.lineTo(x + half, y + half);
      ctx.lineTo(x - half, y + half);
      ctx.closePath();
      break;
    case 'diamond':
      ctx.moveTo(x, y - half);
      ctx.lineTo(x + half, y);
      ctx.lineTo(x, y + half);
      ctx.lineTo(x - half, y);
      ctx.closePath();
      break;
    default:
      ctx.rect(x - half, y - half, size, size);
  }
  ctx.fill();
  ctx.stroke();
  if (typeof style.symbol === 'string' && style.symbol.length === 1) {
    ctx.fillStyle = style.stroke;
    ctx.font = `bold ${Math.round(size * 0.7)}px system-ui, sans-serif`;
    ctx.textAlign = 'center';
    ctx.textBaseline = 'middle';
    ctx.fillText(style.symbol, x, y + 1);
  }
  ctx.restore();
}

/** Draws a cross over (x, y), e.g. on a locked location. */
export function drawCross(ctx, x, y, size, colour) {
  ctx.save();
  ctx.strokeStyle = colour;
  ctx.lineWidth = 3;
  ctx.beginPath();
  ctx.moveTo(x - size, y - size);
  ctx.lineTo(x + size, y + size);
  ctx.moveTo(x + size, y - size);
  ctx.lineTo(x - size, y + size);
  ctx.stroke();
  ctx.restore();
}

/** [value], kept between [min] and [max]. */
export function clamp(value, min, max) {
  return Math.max(min, Math.min(max, value));
}
