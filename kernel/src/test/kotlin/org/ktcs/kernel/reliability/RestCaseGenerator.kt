package org.ktcs.kernel.reliability

import java.net.URLEncoder
import kotlin.random.Random

/** Generates [RestCase]s from a seed: the same seed, the same requests. */
class RestCaseGenerator(seed: Long) {
    private val random = Random(seed)

    fun next(): RestCase = when (random.nextInt(100)) {
        in 0..29 -> RestCase("POST", "/transportOrders/${name()}", orderBody(), contentType())

        in 30..37 -> RestCase("POST", "/orderSequences/${name()}", sequenceBody(), contentType())

        in 38..43 -> RestCase("POST", "/transportOrders/${name()}/withdrawal${query("immediate", bool())}", null, null)

        in 44..47 -> RestCase(
            "PUT",
            "/transportOrders/${name()}/intendedVehicle${query("vehicle", vehicle())}",
            null,
            null,
        )

        in 48..50 -> RestCase("PUT", "/orderSequences/${name()}/complete", null, null)

        in 51..58 -> RestCase("PUT", "/vehicles/${vehicle()}/${vehicleSetting()}", maybeJunk(), contentType())

        in 59..62 -> RestCase(
            "POST",
            "/vehicles/${vehicle()}/${pick("withdrawal", "rerouteRequest", "message")}${query("immediate", bool())}",
            maybeJunk(),
            contentType(),
        )

        in 63..66 -> RestCase("POST", "/vehicles/${vehicle()}/routeComputationQuery", json(), contentType())

        in 67..70 -> RestCase(
            "PUT",
            "/${pick("paths", "locations")}/${encode(pick(*RESOURCES))}/locked${query("newValue", bool())}",
            null,
            null,
        )

        in 71..74 -> RestCase("POST", "/plantModel/topologyUpdateRequest", json(), contentType())

        in 75..76 -> RestCase("PUT", "/plantModel", pick(json(), junk(), "{\"name\":1}"), contentType())

        in 77..82 -> RestCase("GET", get(), null, null)

        in 83..86 -> RestCase(
            pick("PATCH", "DELETE", "PUT", "POST", "HEAD", "OPTIONS"),
            pick("/transportOrders", "/vehicles", "/kernel", "/kernel/version", "/nope", "/ws"),
            maybeJunk(),
            contentType(),
            origin(),
        )

        in 87..90 -> RestCase(
            "POST",
            "/transportOrders/${name()}",
            orderBody(),
            pick("text/plain", "application/x-www-form-urlencoded", "multipart/form-data"),
            origin(),
        )

        in 91..94 -> RestCase("POST", "/dispatcher/trigger", null, null, origin())

        else -> RestCase("POST", "/transportOrders/${name()}", bigBody(), "application/json")
    }

    private fun get(): String = pick(
        "/transportOrders${query("intendedVehicle", vehicle())}",
        "/transportOrders/${name()}",
        "/orderSequences${query("intendedVehicle", vehicle())}",
        "/vehicles${query("procState", pick("IDLE", "AWAITING_ORDER", "PROCESSING_ORDER", text()))}",
        "/vehicles/${vehicle()}",
        "/vehicles/${vehicle()}/commAdapter/attachmentInformation",
        "/events${query("minSequenceNo", number())}&timeout=${pick("0", "10", "-1", "99999999", "x")}",
        "/plantModel",
        "/kernel/version",
    )

    private fun vehicleSetting(): String = pick(
        "integrationLevel${query(
            "newValue",
            pick("TO_BE_IGNORED", "TO_BE_NOTICED", "TO_BE_RESPECTED", "TO_BE_UTILIZED", text()),
        )}",
        "paused${query("newValue", bool())}",
        "allowedOrderTypes",
        "acceptableOrderTypes",
        "energyLevelThresholdSet",
        "envelopeKey${query("newValue", text())}",
        "commAdapter/enabled${query("newValue", bool())}",
        "commAdapter/attachment${query("newValue", pick("loopback", "step", text()))}",
    )

    private fun orderBody(): String = when (random.nextInt(6)) {
        0 -> junk()

        1 -> json()

        2 -> validOrder()

        else -> buildString {
            append("{")
            val fields = mutableListOf<String>()
            if (random.nextInt(8) != 0) fields += "\"destinations\":${destinations()}"
            if (random.nextBoolean()) fields += "\"properties\":${properties()}"
            if (random.nextInt(4) == 0) fields += "\"intendedVehicle\":${value(vehicleName())}"
            if (random.nextInt(4) == 0) {
                fields += "\"deadline\":${value(pick("2030-01-01T00:00:00Z", "yesterday", "-1", text()))}"
            }
            if (random.nextInt(4) == 0) fields += "\"dependencies\":[${value(text())}]"
            if (random.nextInt(4) == 0) fields += "\"wrappingSequence\":${value(text())}"
            if (random.nextInt(4) == 0) fields += "\"type\":${value(text())}"
            if (random.nextInt(4) == 0) fields += "\"incompleteName\":${pick("true", "false", "1", "\"yes\"")}"
            if (random.nextInt(6) == 0) fields += "\"${text()}\":${json()}"
            append(fields.shuffled(random).joinToString(","))
            append("}")
        }
    }

    /** An order the kernel accepts, maybe with a property or intended vehicle, so that creation is exercised too. */
    private fun validOrder(): String {
        val (location, operation) = pick(
            "Storage 01" to "Load cargo",
            "Goods out 01" to "Unload cargo",
            "Point-0001" to "MOVE",
        )
        val extra =
            pick(
                "",
                ",\"properties\":[{\"key\":\"k\",\"value\":\"v\"}]",
                ",\"intendedVehicle\":\"Vehicle-02\"",
                ",\"incompleteName\":true",
            )
        return "{\"destinations\":[{\"locationName\":\"$location\",\"operation\":\"$operation\"}]$extra}"
    }

    private fun sequenceBody(): String = pick(
        "{}",
        "{\"failureFatal\":${bool()},\"properties\":${properties()}}",
        "{\"intendedVehicle\":${value(vehicleName())},\"orderTypes\":[${value(text())}]}",
        json(),
        junk(),
    )

    private fun destinations(): String = "[" + List(random.nextInt(4)) {
        "{\"locationName\":${value(
            pick(*LOCATIONS, *RESOURCES, text()),
        )},\"operation\":${value(pick(*OPERATIONS, text()))}" +
            (if (random.nextBoolean()) ",\"properties\":${properties()}" else "") + "}"
    }.joinToString(",") + "]"

    private fun properties(): String = "[" + List(random.nextInt(3)) {
        "{\"key\":${value(text())},\"value\":${value(text())}}"
    }.joinToString(",") + "]"

    /** A JSON string literal of [text], with its hostile characters escaped as JSON allows. */
    private fun value(text: String): String = if (random.nextInt(20) == 0) {
        "null"
    } else {
        buildString {
            append('"')
            text.forEach { c ->
                when {
                    c == '"' -> append("\\\"")
                    c == '\\' -> append("\\\\")
                    c < ' ' -> append("\\u%04x".format(c.code))
                    else -> append(c)
                }
            }
            append('"')
        }
    }

    /** Any JSON value, up to a small depth. */
    private fun json(depth: Int = 0): String = when (if (depth > 3) random.nextInt(4) else random.nextInt(7)) {
        0 -> value(text())

        1 -> number()

        2 -> pick("true", "false", "null")

        3 -> "\"\""

        4 -> "[" + List(random.nextInt(4)) { json(depth + 1) }.joinToString(",") + "]"

        else ->
            "{" +
                List(random.nextInt(4)) {
                    "${value(pick("destinations", "paths", "name", "key", text()))}:${json(depth + 1)}"
                }
                    .joinToString(",") + "}"
    }

    private fun junk(): String = pick(
        "{",
        "{\"destinations\":[{\"locationName\":",
        "null",
        "[]",
        "\u0000\u0001\u0002",
        "<tcsOrderSet/>",
        "{\"destinations\":" + "[".repeat(2_000),
        String(CharArray(random.nextInt(64)) { (random.nextInt(0x20, 0x7f)).toChar() }),
    )

    private fun maybeJunk(): String? = if (random.nextBoolean()) null else pick(json(), junk())

    private fun bigBody(): String =
        "{\"destinations\":[],\"type\":\"" + "x".repeat(random.nextInt(1, 3) * 1024 * 1024) + "\"}"

    private fun contentType(): String? = pick(
        "application/json",
        "application/json",
        "application/json; charset=utf-8",
        null,
        "text/plain",
        "application/json; charset=nonsense",
        ";;;",
        "application/json; charset",
    )

    private fun origin(): Map<String, String> = if (random.nextBoolean()) {
        emptyMap()
    } else {
        mapOf("Origin" to pick("http://evil.example", "null"))
    }

    private fun name(): String = encode(
        pick("Order-${random.nextInt(50)}", "T", text(), "a/b", ".", "..", "x".repeat(random.nextInt(1, 3000))),
    )

    private fun vehicle(): String = encode(vehicleName())

    private fun vehicleName(): String = pick("Vehicle-01", "Vehicle-02", "Vehicle-03", "Vehicle-04", "Ghost", text())

    private fun text(): String = when (random.nextInt(8)) {
        0 -> ""
        1 -> " "
        2 -> "Ctl-" + random.nextInt(0, 0x20).toChar() + "x"
        3 -> "\uFFFF\uD800"
        4 -> "日本語 Ünïcödé"
        5 -> "<&>\"'|"
        6 -> "x".repeat(random.nextInt(1, 500))
        else -> "Name-${random.nextInt(1000)}"
    }

    private fun number(): String = pick("0", "-1", "1e308", "9223372036854775808", "NaN", "0.5", "${random.nextLong()}")

    private fun bool(): String = pick("true", "false", "TRUE", "", "1", "maybe")

    private fun query(name: String, value: String): String = "?$name=${encode(value)}"

    private fun encode(text: String): String = URLEncoder.encode(text, Charsets.UTF_8).replace("+", "%20")

    private fun <T> pick(vararg options: T): T = options[random.nextInt(options.size)]

    private companion object {
        val LOCATIONS = arrayOf("Storage 01", "Storage 02", "Goods in north 01", "Goods out 01", "Recharge 01")
        val OPERATIONS = arrayOf("Load cargo", "Unload cargo", "MOVE", "PARK", "NOP", "CHARGE", "Drill")
        val RESOURCES = arrayOf("Point-0001", "Point-0028", "Point-0001 --- Point-0002", "Storage 01", "Nowhere")
    }
}
