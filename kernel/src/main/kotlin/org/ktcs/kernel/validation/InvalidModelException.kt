package org.ktcs.kernel.validation

/**
 * Thrown when a plant model has errors and must not be loaded.
 *
 * The message lists every error, one per line; warnings stay available in [problems] but are not listed.
 */
class InvalidModelException(val modelName: String, val problems: List<ModelProblem>) :
    IllegalArgumentException(describe(modelName, problems.filter { it.isError }))

private fun describe(modelName: String, errors: List<ModelProblem>): String {
    val noun = if (errors.size == 1) "error" else "errors"
    val summary = "plant model '$modelName' has ${errors.size} $noun:"
    return (listOf(summary) + errors.map { "  $it" }).joinToString("\n")
}
