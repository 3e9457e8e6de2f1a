// kTCS's default vehicle theme: the fill says what the vehicle does, the outline whether it is paused or ignored.

const FILL_BY_STATE = {
  IDLE: '#90caf9',
  EXECUTING: '#66bb6a',
  CHARGING: '#ffd54f',
  ERROR: '#ef5350',
  UNAVAILABLE: '#bdbdbd',
  UNKNOWN: '#e0e0e0',
};

export default {
  vehicleStyle(vehicle) {
    const state = vehicle.state?.state ?? 'UNKNOWN';
    const ignored = vehicle.integrationLevel === 'TO_BE_IGNORED' || vehicle.integrationLevel === 'TO_BE_NOTICED';
    return {
      fill: ignored ? '#eeeeee' : FILL_BY_STATE[state] ?? FILL_BY_STATE.UNKNOWN,
      stroke: vehicle.paused ? '#ef6c00' : '#263238',
      label: vehicle.name,
    };
  },
};
