package org.ktcs.kernel.vehicles

import org.ktcs.api.driver.DriverCommand
import org.ktcs.api.driver.DriverPanel
import org.ktcs.api.driver.DriverParameter
import org.ktcs.api.driver.ParameterType
import org.ktcs.api.error.InvalidRequestException
import org.ktcs.api.model.PlantModel

/**
 * Checks a command for a driver against its [DriverPanel] before the driver sees it: the command must be declared,
 * every required parameter present, no undeclared one given and every value of its type. Returns the parameters as
 * the driver gets them (choices spelled as declared, surrounding blanks trimmed).
 */
internal object DriverCommandCheck {
    fun check(
        panel: DriverPanel,
        driver: String,
        name: String,
        parameters: Map<String, String>,
        plant: PlantModel,
    ): Map<String, String> {
        val command = panel.command(name) ?: throw InvalidRequestException(
            "driver '$driver' has no command '$name'; it has: ${panel.commands.joinToString {
                it.name
            }.ifEmpty { "none" }}",
        )
        val unknown = parameters.keys - command.parameters.map { it.name }.toSet()
        if (unknown.isNotEmpty()) {
            throw InvalidRequestException("command '$name' has no parameter ${unknown.joinToString { "'$it'" }}")
        }
        return command.parameters.mapNotNull { parameter ->
            val raw = parameters[parameter.name]?.trim()
            when {
                raw != null -> parameter.name to checked(command, parameter, raw, plant)

                parameter.required -> throw InvalidRequestException(
                    "command '$name' needs parameter '${parameter.name}' (${describe(parameter)})",
                )

                else -> null
            }
        }.toMap()
    }

    private fun checked(command: DriverCommand, parameter: DriverParameter, raw: String, plant: PlantModel): String {
        fun bad(): Nothing = throw InvalidRequestException(
            "command '${command.name}': parameter '${parameter.name}' must be ${describe(parameter)}, was '$raw'",
        )
        return when (parameter.type) {
            ParameterType.TEXT -> raw

            ParameterType.INTEGER -> raw.toLongOrNull()?.takeIf { inRange(parameter, it.toDouble()) }?.toString()
                ?: bad()

            ParameterType.NUMBER -> raw.toDoubleOrNull()?.takeIf { it.isFinite() && inRange(parameter, it) }
                ?.let { raw } ?: bad()

            ParameterType.BOOLEAN -> raw.lowercase().toBooleanStrictOrNull()?.toString() ?: bad()

            ParameterType.CHOICE -> parameter.values.firstOrNull { it.equals(raw, ignoreCase = true) } ?: bad()

            ParameterType.POINT -> plant.point(raw)?.name ?: bad()
        }
    }

    private fun inRange(parameter: DriverParameter, value: Double) =
        (parameter.min == null || value >= parameter.min!!) && (parameter.max == null || value <= parameter.max!!)

    private fun describe(parameter: DriverParameter): String = when (parameter.type) {
        ParameterType.TEXT -> "text"
        ParameterType.INTEGER -> "a whole number${range(parameter)}"
        ParameterType.NUMBER -> "a number${range(parameter)}"
        ParameterType.BOOLEAN -> "true or false"
        ParameterType.CHOICE -> "one of ${parameter.values.joinToString()}"
        ParameterType.POINT -> "the name of a point of the plant model"
    }

    private fun range(parameter: DriverParameter): String = when {
        parameter.min != null && parameter.max != null -> " from ${plain(parameter.min!!)} to ${plain(parameter.max!!)}"
        parameter.min != null -> " of at least ${plain(parameter.min!!)}"
        parameter.max != null -> " of at most ${plain(parameter.max!!)}"
        else -> ""
    }

    private fun plain(value: Double) = if (value % 1.0 == 0.0) value.toLong().toString() else value.toString()
}
