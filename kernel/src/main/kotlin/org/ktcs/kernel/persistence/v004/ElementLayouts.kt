package org.ktcs.kernel.persistence.v004

import org.ktcs.api.model.BlockLayout
import org.ktcs.api.model.Couple
import org.ktcs.api.model.LocationLayout
import org.ktcs.api.model.PathLayout
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.PointLayout
import org.ktcs.api.model.VehicleLayout
import org.ktcs.api.model.VisualLayout
import org.ktcs.kernel.persistence.ReadWarnings
import org.ktcs.kernel.persistence.v7.toCouples
import org.ktcs.kernel.persistence.v7.toDomain

/**
 * Converts a 0.0.4 or 0.0.5 file as described at [LegacyPlantModelTO.toDomain]. The layout positions of points and
 * locations (`pointLayout`/`locationLayout` `xPosition`, `yPosition`) win where they differ from the model positions
 * (see [DrawnPositions]).
 */
internal fun V004PlantModelTO.toDomain(warnings: ReadWarnings): PlantModel = toDomain(
    ElementLayouts(visualLayout?.toDomain() ?: VisualLayout()),
    warnings,
)

/** 0.0.4 and 0.0.5 keep each element's layout in a child element, as 7.0.0 does. */
private class ElementLayouts(private val visualLayout: VisualLayout) : LegacyLayouts {
    override fun point(to: PointTO) =
        to.pointLayout?.let { PointLayout(Couple(it.xLabelOffset, it.yLabelOffset), it.layerId) } ?: PointLayout()

    override fun path(to: PathTO) =
        to.pathLayout?.let { PathLayout(it.connectionType, it.controlPoint.toCouples(), it.layerId) } ?: PathLayout()

    override fun vehicleColor(to: VehicleTO) = to.vehicleLayout?.color ?: VehicleLayout().routeColor

    override fun location(to: LocationTO): LocationLayout {
        val layout = to.locationLayout ?: return LocationLayout()
        val symbol = layout.locationRepresentation ?: LocationLayout().locationRepresentation
        return LocationLayout(Couple(layout.xLabelOffset, layout.yLabelOffset), symbol, layout.layerId)
    }

    override fun blockColor(to: BlockTO) = to.blockLayout?.color ?: BlockLayout().color

    override fun visualLayout() = visualLayout

    override fun drawnPosition(to: PointTO) = to.pointLayout?.let { Couple(it.xPosition, it.yPosition) }

    override fun drawnPosition(to: LocationTO) = to.locationLayout?.let { Couple(it.xPosition, it.yPosition) }
}
