package org.ktcs.adapters.vda5050.protocol

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.ints.shouldBeGreaterThan
import io.kotest.matchers.nulls.shouldNotBeNull
import io.kotest.matchers.shouldBe
import kotlin.random.Random

private val state = MessageValidator.quickSchema(IncomingTopic.STATE)!!

private fun slice(text: String) = text.toByteArray().let { ByteSlice(it, 0, it.size) }

/** What the schema validator says of [value] as the state field [name]: empty when it is valid. */
private fun validatorProblems(name: String, value: String) = try {
    MessageValidator.stateFieldProblems(MessageValidator.read("{\"$name\":$value}".toByteArray()))
} catch (error: tools.jackson.core.JacksonException) {
    listOf("not JSON")
}

/** JSON-ish values, well-formed or not, near what a vehicle sends for [name]'s schema: mostly plausible, some not. */
private class Values(private val random: Random) {
    private val words = listOf("AUTOMATIC", "NONE", "FINISHED", "RUNNING", "WAITING", "Point-1", "", "x y", "ASLEEP")
    private val names = listOf(
        "x", "y", "theta", "mapId", "positionInitialized", "batteryCharge", "charging", "nodeId", "sequenceId",
        "released", "edgeId", "actionId", "actionStatus", "actionType", "localizationScore", "deviationRange",
        "batteryHealth", "reach", "eStop", "fieldViolation", "errorType", "errorLevel", "loadId", "nodePosition",
    )

    fun value(depth: Int = 0): String = when (random.nextInt(if (depth > 3) 10 else 13)) {
        0, 1 -> number()
        2 -> random.nextLong(-5, 100_000).toString()
        3, 4 -> "\"${words.random(random)}\""
        5 -> listOf("true", "false", "null", "tru", "nul", "True").random(random)
        6 -> "\"${listOf("a\\\"b", "\\u0041UTOMATIC", "Pünkt", "tab\there", "a\\nb", "\\").random(random)}\""
        7 -> listOf("01", "-", "1.", ".5", "1e", "--1", "+1", "1.0", "1e2", "-0", "1E+2", "0.5e-3").random(random)
        8 -> "${random.nextInt(-3, 3)}.${random.nextInt(0, 99)}"
        9 -> listOf("", " ", "{", "[", "}", "\"open", "1 2", "[1,]", "{\"x\":1,}").random(random)
        else -> if (random.nextBoolean()) obj(depth) else array(depth)
    }

    private fun number() = (random.nextDouble(-2.0, 2.0) * listOf(1.0, 100.0, 1e6).random(random)).toString()

    fun obj(depth: Int = 0): String {
        val members = (0 until random.nextInt(0, 8)).map { "\"${names.random(random)}\":${value(depth + 1)}" }
        return members.joinToString(if (random.nextInt(20) == 0) " , " else ",", "{", "}")
    }

    /** One of [templates] (valid objects) with a member changed to a random value, dropped, doubled or added. */
    fun nearly(templates: List<List<Pair<String, String>>>): String {
        val members = templates.random(random).toMutableList()
        val i = random.nextInt(members.size)
        when (random.nextInt(6)) {
            0 -> members[i] = members[i].first to value(2)
            1 -> members.removeAt(i)
            2 -> members += members[i].first to value(2)
            3 -> members += names.random(random) to value(2)
            else -> Unit
        }
        return members.joinToString(",", "{", "}") { (name, value) -> "\"$name\":$value" }
    }

    fun array(depth: Int = 0): String =
        (0 until random.nextInt(0, 4)).joinToString(",", "[", "]") {
            if (random.nextBoolean()) obj(depth + 1) else value(depth + 1)
        }
}

/**
 * A quick schema checks a value by its bytes, and says yes only where the schema validator does: anything it is not
 * sure of is left to the validator, whose words then name the problem.
 */
class QuickSchemaTest : FunSpec({
    test("the state and visualization schemas are quick schemas") {
        MessageValidator.quickSchema(IncomingTopic.VISUALIZATION).shouldNotBeNull()
        listOf("headerId", "timestamp", "agvPosition", "batteryState", "lastNodeId", "driving", "operatingMode")
            .forEach { state.property(it).shouldNotBeNull() }
        listOf("nodeStates", "edgeStates", "actionStates", "errors", "loads").forEach {
            state.property(it)?.items.shouldNotBeNull()
        }
    }

    test("what a moving vehicle's fields change to is accepted by its bytes") {
        mapOf(
            "headerId" to "4711",
            "timestamp" to "\"2026-12-01T11:12:19.712693130Z\"",
            "agvPosition" to "{\"x\":-2.5,\"y\":1.25,\"theta\":1.5707963,\"mapId\":\"\",\"positionInitialized\":true}",
            "batteryState" to "{ \"batteryCharge\" : 79.25, \"charging\" : false }",
            "lastNodeSequenceId" to "52",
            "driving" to "true",
            "distanceSinceLastNode" to "0.3",
            "operatingMode" to "\"AUTOMATIC\"",
        ).forEach { (name, value) ->
            validatorProblems(name, value).shouldBeEmpty()
            state.property(name)!!.accepts(slice(value)) shouldBe true
        }
        val node = "{\"nodeId\":\"P-12-13\",\"sequenceId\":54,\"released\":true}"
        state.property("nodeStates")!!.items!!.accepts(slice(node)) shouldBe true
        val action = "{\"actionId\":\"a-1\",\"actionType\":\"pick\",\"actionStatus\":\"FINISHED\"}"
        state.property("actionStates")!!.items!!.accepts(slice(action)) shouldBe true
    }

    test("what it cannot be sure of is left to the validator, which accepts some and rejects others") {
        mapOf(
            "headerId" to listOf("1.0", "1e2", "1.5", "\"1\"", "01", "12 3"),
            "orderId" to listOf("\"o-\\u0032\"", "\"Pünkt\"", "\"tab\there\"", "1"),
            "operatingMode" to listOf("\"ASLEEP\"", "\"AUTOMATI\\u0043\""),
            "agvPosition" to listOf(
                "{\"x\":1,\"y\":2,\"theta\":0,\"mapId\":\"m\",\"positionInitialized\":true,\"x\":\"s\"}",
                "{\"x\":1,\"y\":2,\"theta\":0,\"mapId\":\"m\"}",
                "{\"x\":1,\"y\":2,\"theta\":0,\"mapId\":\"m\",\"positionInitialized\":true,\"localizationScore\":1.5}",
            ),
            "batteryState" to listOf("{\"batteryCharge\":50,\"charging\":false,\"batteryHealth\":2.0}"),
        ).forEach { (name, values) ->
            values.forEach { state.property(name)!!.accepts(slice(it)) shouldBe false }
        }
        validatorProblems("headerId", "1.0").shouldBeEmpty()
        validatorProblems("orderId", "\"o-\\u0032\"").shouldBeEmpty()
    }

    test("nesting deeper than a message needs is left to the validator, without running out of stack") {
        val deep = "[".repeat(100_000) + "]".repeat(100_000)
        state.property("information")!!.accepts(slice(deep)) shouldBe false
        state.property("loads")!!.items!!.accepts(slice("{\"loadId\":${"[".repeat(50)}${"]".repeat(50)}}")) shouldBe
            false
    }

    test("of thousands of random values, every one accepted by its bytes is valid to the validator") {
        val random = Random(5050)
        val values = Values(random)
        var accepted = 0
        val fields = listOf(
            "headerId", "timestamp", "orderUpdateId", "lastNodeId", "lastNodeSequenceId", "driving", "operatingMode",
            "agvPosition", "batteryState", "safetyState", "distanceSinceLastNode", "paused",
        )
        repeat(20_000) {
            val name = fields.random(random)
            val value = if (random.nextBoolean()) values.obj() else values.value()
            if (state.property(name)!!.accepts(slice(value))) {
                accepted++
                withClue(name, value) { validatorProblems(name, value).shouldBeEmpty() }
            }
        }
        val templates = listOf(
            listOf("x" to "1.5", "y" to "-2", "theta" to "0.1", "mapId" to "\"m\"", "positionInitialized" to "true"),
            listOf("batteryCharge" to "80.5", "charging" to "false"),
            listOf("eStop" to "\"NONE\"", "fieldViolation" to "false"),
            listOf("nodeId" to "\"P-1\"", "sequenceId" to "2", "released" to "true"),
            listOf("edgeId" to "\"P-1 --- P-2\"", "sequenceId" to "3", "released" to "false"),
            listOf("actionId" to "\"a\"", "actionType" to "\"pick\"", "actionStatus" to "\"RUNNING\""),
            listOf("errorType" to "\"e\"", "errorLevel" to "\"WARNING\"", "errorReferences" to "[]"),
            listOf("infoType" to "\"i\"", "infoLevel" to "\"INFO\""),
        )
        val elements = listOf("nodeStates", "edgeStates", "actionStates", "errors", "loads", "information")
        repeat(20_000) {
            val name = listOf("agvPosition", "batteryState", "safetyState").random(random)
            val value = values.nearly(templates)
            if (state.property(name)!!.accepts(slice(value))) {
                accepted++
                withClue(name, value) { validatorProblems(name, value).shouldBeEmpty() }
            }
        }
        repeat(20_000) {
            val name = elements.random(random)
            val value = if (random.nextBoolean()) values.obj() else values.nearly(templates)
            if (state.property(name)!!.items!!.accepts(slice(value))) {
                accepted++
                withClue(name, value) { validatorProblems(name, "[$value]").shouldBeEmpty() }
            }
        }
        accepted shouldBeGreaterThan 3_000
    }
})

private fun withClue(name: String, value: String, check: () -> Unit) =
    io.kotest.assertions.withClue("$name = $value") { check() }
