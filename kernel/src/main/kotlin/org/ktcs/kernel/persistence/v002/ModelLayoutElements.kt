package org.ktcs.kernel.persistence.v002

import org.ktcs.api.model.ConnectionType
import org.ktcs.api.model.Couple
import org.ktcs.api.model.LocationLayout
import org.ktcs.api.model.PathLayout
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.PointLayout
import org.ktcs.api.model.VisualLayout
import org.ktcs.kernel.persistence.ModelFileException
import org.ktcs.kernel.persistence.ReadWarnings
import org.ktcs.kernel.persistence.toMap
import org.ktcs.kernel.persistence.v004.BlockTO
import org.ktcs.kernel.persistence.v004.DrawnPositions
import org.ktcs.kernel.persistence.v004.LegacyLayouts
import org.ktcs.kernel.persistence.v004.LegacyPlantModelTO
import org.ktcs.kernel.persistence.v004.LocationTO
import org.ktcs.kernel.persistence.v004.PathTO
import org.ktcs.kernel.persistence.v004.PointTO
import org.ktcs.kernel.persistence.v004.VehicleTO
import org.ktcs.kernel.persistence.v004.toDomain

/**
 * Converts a 0.0.2 or 0.0.3 file as openTCS 5 converted it to 0.0.4, then like any file older than 6.0.0 (see
 * [LegacyPlantModelTO.toDomain]). Element layouts come from the first visual layout's
 * `modelLayoutElement` properties: `LABEL_OFFSET_X`/`_Y` (default 0), `CONN_TYPE` (default DIRECT), `CONTROL_POINTS`
 * (`x,y;x,y`), `ROUTE_COLOR` and block `COLOR` (default red). Every element is on the default layer, and the visual
 * layout gets the default layer and layer group. Layout positions (`POSITION_X`/`_Y`) that differ from the model
 * positions win (see [DrawnPositions]).
 *
 * Dropped, having no place in 7.0.0: the 4.x concepts `vehicleType`, `staticRoute` and `group`; path `routingCost`
 * and the per-vehicle-type `typeMaxVelocity`, `typeMaxReverseVelocity`, `typeLock` and `typeActions`; vehicle `type`;
 * location type `locationNamePrefix`; the `id` attributes; the `layer` numbers of model layout elements; shape layout elements, view bookmarks and colours of the visual layout; every
 * visual layout after the first.
 */
internal fun V002PlantModelTO.toDomain(source: String, warnings: ReadWarnings): PlantModel =
    toDomain(ModelLayoutElements(visualLayout, source), warnings)

private class ModelLayoutElements(layouts: List<V002VisualLayoutTO>, private val source: String) : LegacyLayouts {
    private val first = layouts.firstOrNull()
    private val byName = first?.modelLayoutElement.orEmpty().associate {
        it.visualizedObjectName to it.property.toMap()
    }

    override fun point(to: PointTO) = PointLayout(labelOffset(to.name))

    override fun path(to: PathTO): PathLayout {
        val properties = byName[to.name].orEmpty()
        val type = properties["CONN_TYPE"]?.let { value ->
            ConnectionType.entries.firstOrNull { it.name == value } ?: throw bad(to.name, "CONN_TYPE", value)
        }
        return PathLayout(type ?: ConnectionType.DIRECT, controlPoints(to.name, properties["CONTROL_POINTS"]))
    }

    override fun vehicleColor(to: VehicleTO) = color(to.name, "ROUTE_COLOR")

    override fun location(to: LocationTO) = LocationLayout(labelOffset(to.name))

    override fun blockColor(to: BlockTO) = color(to.name, "COLOR")

    override fun drawnPosition(to: PointTO) = drawnPosition(to.name)

    override fun drawnPosition(to: LocationTO) = drawnPosition(to.name)

    private fun drawnPosition(name: String): Couple? {
        val properties = byName[name] ?: return null
        if ("POSITION_X" !in properties || "POSITION_Y" !in properties) return null
        return Couple(number(name, "POSITION_X"), number(name, "POSITION_Y"))
    }

    override fun visualLayout(): VisualLayout =
        first?.let { VisualLayout(it.name, it.scaleX, it.scaleY, properties = it.property.toMap()) } ?: VisualLayout()

    private fun labelOffset(name: String) = Couple(number(name, "LABEL_OFFSET_X"), number(name, "LABEL_OFFSET_Y"))

    private fun number(name: String, key: String): Long {
        val value = byName[name]?.get(key) ?: return 0
        return value.trim().toLongOrNull() ?: throw bad(name, key, value)
    }

    private fun color(name: String, key: String): String = byName[name]?.get(key)?.uppercase() ?: RED

    private fun controlPoints(name: String, value: String?): List<Couple> =
        value?.split(';')?.filter { it.isNotBlank() }?.map { point ->
            val xy = point.split(',').map { it.trim().toLongOrNull() }
            val x = xy.getOrNull(0)
            val y = xy.getOrNull(1)
            if (xy.size != 2 || x == null || y == null) throw bad(name, "CONTROL_POINTS", value)
            Couple(x, y)
        }.orEmpty()

    private fun bad(name: String, key: String, value: String) = ModelFileException(
        "$source: invalid layout property $key=\"$value\" in <modelLayoutElement visualizedObjectName=\"$name\">",
    )

    private companion object {
        const val RED = "#FF0000"
    }
}
