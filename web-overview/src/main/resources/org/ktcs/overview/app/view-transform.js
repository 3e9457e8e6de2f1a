// Maps model coordinates (mm, y up) to canvas pixels and back; pan and zoom change it.

export class ViewTransform {
  constructor() {
    this.scale = 0.05;
    this.offsetX = 0;
    this.offsetY = 0;
  }

  toScreen(x, y) {
    return { x: x * this.scale + this.offsetX, y: -y * this.scale + this.offsetY };
  }

  toModel(x, y) {
    return { x: (x - this.offsetX) / this.scale, y: -(y - this.offsetY) / this.scale };
  }

  /** The model rectangle a canvas of this size shows. */
  visibleRect(width, height) {
    const a = this.toModel(0, 0);
    const b = this.toModel(width, height);
    return { minX: Math.min(a.x, b.x), maxX: Math.max(a.x, b.x), minY: Math.min(a.y, b.y), maxY: Math.max(a.y, b.y) };
  }

  fit(bounds, width, height, margin = 70) {
    const modelWidth = Math.max(1, bounds.maxX - bounds.minX);
    const modelHeight = Math.max(1, bounds.maxY - bounds.minY);
    this.scale = Math.min((width - 2 * margin) / modelWidth, (height - 2 * margin) / modelHeight);
    if (!(this.scale > 0)) this.scale = 0.05;
    this.offsetX = width / 2 - ((bounds.minX + bounds.maxX) / 2) * this.scale;
    this.offsetY = height / 2 + ((bounds.minY + bounds.maxY) / 2) * this.scale;
  }

  zoomAt(factor, screenX, screenY) {
    const anchor = this.toModel(screenX, screenY);
    this.scale = Math.min(50, Math.max(1e-5, this.scale * factor));
    this.offsetX = screenX - anchor.x * this.scale;
    this.offsetY = screenY + anchor.y * this.scale;
  }

  /** Puts model point (x, y) in the middle of a canvas of this size, at the current scale. */
  centreOn(x, y, width, height) {
    this.offsetX = width / 2 - x * this.scale;
    this.offsetY = height / 2 + y * this.scale;
  }

  pan(dx, dy) {
    this.offsetX += dx;
    this.offsetY += dy;
  }
}
