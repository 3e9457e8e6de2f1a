// snippet:vehicle-theme
// Colours each vehicle by its energy: red at or below its critical level, amber below good, green otherwise.
// The vehicle is the object of the WebSocket topic "vehicles"; missing fields fall back to the default theme.
export function energyColour(vehicle) {
  const thresholds = vehicle.energyLevelThresholdSet || {};
  const critical = thresholds.energyLevelCritical ?? 30;
  const good = thresholds.energyLevelGood ?? 90;
  if (vehicle.energyLevel <= critical) return "#d32f2f";
  if (vehicle.energyLevel < good) return "#f9a825";
  return "#2e7d32";
}

export default {
  vehicleStyle(vehicle) {
    return {
      fill: energyColour(vehicle),
      stroke: vehicle.paused ? "#000000" : "#424242",
      label: `${vehicle.name} ${vehicle.energyLevel}%`,
    };
  },
};
// end-snippet
