package org.ktcs.examples.tcpdriver

/**
 * The example vehicle's protocol: one message per line, fields separated by `|`, the first field naming the
 * message. Names in the plant (points, locations, operations) may contain spaces but not `|` or line breaks.
 *
 * kTCS to the vehicle:
 * - `COMMAND|id|destination point|operation|location` (location `-` when there is none): drive there, then operate
 * - `CLEAR`: drop every command not finished yet
 * - `PAUSE|true` / `PAUSE|false`
 * - `MESSAGE|type|key=value|...`: a message from a kTCS client
 *
 * The vehicle to kTCS:
 * - `POSITION|point` (empty: unknown), `ENERGY|percent`, `STATE|IDLE` (a kTCS vehicle state)
 * - `EXECUTED|id` / `FAILED|id`: a command is done or cannot be done
 * - `PROPERTY|key|value` (empty value: remove), `EVENT|type|key=value|...`
 */
object LineProtocol {
    const val SEPARATOR = '|'
    const val NO_LOCATION = "-"

    fun command(id: Long, point: String, operation: String, location: String?): String =
        line("COMMAND", id.toString(), point, operation, location ?: NO_LOCATION)

    fun clear(): String = "CLEAR"

    fun pause(paused: Boolean): String = line("PAUSE", paused.toString())

    fun message(type: String, parameters: Map<String, String>): String =
        line("MESSAGE", type, *pairs(parameters))

    fun position(point: String?): String = line("POSITION", point.orEmpty())

    fun energy(percent: Int): String = line("ENERGY", percent.toString())

    fun state(state: String): String = line("STATE", state)

    fun executed(id: Long): String = line("EXECUTED", id.toString())

    fun failed(id: Long): String = line("FAILED", id.toString())

    fun property(key: String, value: String?): String = line("PROPERTY", key, value.orEmpty())

    fun event(type: String, payload: Map<String, String>): String = line("EVENT", type, *pairs(payload))

    /** Splits [line] into its message name and fields. */
    fun parse(line: String): Message {
        val fields = line.trimEnd('\r').split(SEPARATOR)
        return Message(fields.first(), fields.drop(1))
    }

    /** `key=value` fields back into a map; a field without `=` is a protocol error. */
    fun parameters(fields: List<String>): Map<String, String> = fields.filter { it.isNotEmpty() }.associate { field ->
        require('=' in field) { "expected key=value, got '$field'" }
        field.substringBefore('=') to field.substringAfter('=')
    }

    private fun pairs(values: Map<String, String>) = values.map { (key, value) -> "$key=$value" }.toTypedArray()

    private fun line(vararg fields: String): String {
        fields.forEach { field ->
            require(SEPARATOR !in field && '\n' !in field && '\r' !in field) {
                "a field of the line protocol must not contain '|' or a line break: '$field'"
            }
        }
        return fields.joinToString(SEPARATOR.toString())
    }

    /** One received line: the message [name] and its [fields]. */
    data class Message(val name: String, val fields: List<String>)
}
