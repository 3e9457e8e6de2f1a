// The panel's own copy of the energy colours: a contribution serves only the files in its own directory.
export function energyColour(vehicle) {
  const thresholds = vehicle.energyLevelThresholdSet || {};
  if (vehicle.energyLevel <= (thresholds.energyLevelCritical ?? 30)) return "#d32f2f";
  if (vehicle.energyLevel < (thresholds.energyLevelGood ?? 90)) return "#f9a825";
  return "#2e7d32";
}
