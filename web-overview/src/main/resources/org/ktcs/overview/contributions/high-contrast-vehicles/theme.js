// A vehicle theme for bright halls and weak eyes: saturated fills, black outlines, white labels on black.

const FILL_BY_STATE = {
  IDLE: '#ffffff',
  EXECUTING: '#00e000',
  CHARGING: '#ffff00',
  ERROR: '#ff0000',
  UNAVAILABLE: '#808080',
  UNKNOWN: '#808080',
};

export default {
  vehicleStyle(vehicle) {
    const state = vehicle.state?.state ?? 'UNKNOWN';
    return {
      fill: FILL_BY_STATE[state] ?? FILL_BY_STATE.UNKNOWN,
      stroke: vehicle.paused ? '#ff00ff' : '#000000',
      lineWidth: 3,
      label: `${vehicle.name} ${vehicle.energyLevel}%`,
      labelColour: '#000000',
    };
  },
};
