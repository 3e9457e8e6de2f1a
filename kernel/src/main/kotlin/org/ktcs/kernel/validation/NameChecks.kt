package org.ktcs.kernel.validation

import org.ktcs.api.model.PlantObject
import org.ktcs.api.model.XmlSafeText

/** Names identify objects of every kind at once, as in openTCS, so a point and a path must not share one. */
internal fun nameProblems(index: ModelIndex): List<ModelProblem> {
    val objects = index.model.allObjects().toList()
    return objects.filter { it.name.isBlank() }.map { it.error("name must not be blank") } +
        objects.mapNotNull { o ->
            XmlSafeText.firstUnsafe(o.name)?.let { o.error("name has a character XML cannot carry: $it") }
        } +
        duplicateNameProblems(objects.filter { it.name.isNotBlank() })
}

private fun duplicateNameProblems(objects: List<PlantObject>): List<ModelProblem> =
    objects.groupBy { it.name }.values
        .filter { it.size > 1 }
        .map { clash -> clash.first().error("name '${clash.first().name}' is used by ${describe(clash)}") }

private fun describe(clash: List<PlantObject>): String = "${clash.size} objects: ${clash.joinToString { it.kind }}"
