package org.ktcs.kernel.validation

/** How bad a [ModelProblem] is. */
enum class Severity {
    /** The model must not be loaded. */
    ERROR,

    /** The model is usable, but probably not what its author meant. */
    WARNING,
}

/**
 * One finding of [PlantModelValidator].
 *
 * @property element the offending element as kind and name, e.g. `path 'A --- B'`.
 * @property message what is wrong, including the bad value.
 */
data class ModelProblem(val severity: Severity, val element: String, val message: String) {
    val isError: Boolean get() = severity == Severity.ERROR

    override fun toString(): String = "$severity $element: $message"
}
