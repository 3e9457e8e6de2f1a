// Loads the vehicle and location themes the configuration selected. A theme may leave out fields (or fail): those
// come from the default theme, so the plant is always drawn.

const LAST_RESORT = {
  vehicleStyle: (vehicle) => ({ fill: '#90a4ae', stroke: '#263238', label: vehicle.name }),
  locationStyle: () => ({ fill: '#e0e0e0', stroke: '#424242', symbol: 'square' }),
};

export async function loadThemes(extensions, settings, notify) {
  const themeModule = async (name) => {
    const entry = extensions.find((e) => e.kind === 'theme' && e.name === name);
    if (!entry) return null;
    try {
      return (await import(entry.module)).default;
    } catch (error) {
      notify(`Theme '${name}' could not be loaded: ${error.message}`, 'error');
      return null;
    }
  };
  const [vehicleDefault, vehicleTheme, locationDefault, locationTheme] = await Promise.all([
    themeModule('default-vehicles'), themeModule(settings.vehicleTheme),
    themeModule('default-locations'), themeModule(settings.locationTheme),
  ]);
  const failed = new Set();
  const reportOnce = (name, error) => {
    if (failed.has(name)) return;
    failed.add(name);
    notify(`Theme '${name}' failed: ${error.message}`, 'error');
  };
  const styleOf = (method, theme, themeName, fallback, args) => {
    const base = (fallback?.[method] ?? LAST_RESORT[method])(...args);
    if (!theme || theme === fallback || typeof theme[method] !== 'function') return base;
    try {
      const own = theme[method](...args) ?? {};
      return { ...base, ...Object.fromEntries(Object.entries(own).filter(([, v]) => v !== undefined && v !== null)) };
    } catch (error) {
      reportOnce(themeName, error);
      return base;
    }
  };
  return {
    vehicleStyle: (vehicle) => styleOf('vehicleStyle', vehicleTheme, settings.vehicleTheme, vehicleDefault, [vehicle]),
    locationStyle: (location, type) =>
      styleOf('locationStyle', locationTheme, settings.locationTheme, locationDefault, [location, type]),
  };
}
