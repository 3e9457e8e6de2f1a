package org.ktcs.kernel.web.v1

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import kotlinx.serialization.json.Json
import org.ktcs.kernel.web.v1.GoldenJson.shouldEqualJsonElement

class GoldenJsonTest : FunSpec({
    test("ignores property order") {
        """{"b":1,"a":[{"y":null,"x":"s"}]}""" shouldEqualJsonElement
            Json.parseToJsonElement("""{"a":[{"x":"s","y":null}],"b":1}""")
    }

    test("tells apart values, nulls, absent fields, strings and numbers") {
        val expected = Json.parseToJsonElement("""{"a":1,"b":null}""")

        shouldThrow<AssertionError> { """{"a":2,"b":null}""" shouldEqualJsonElement expected }
        shouldThrow<AssertionError> { """{"a":1}""" shouldEqualJsonElement expected }
        shouldThrow<AssertionError> { """{"a":"1","b":null}""" shouldEqualJsonElement expected }
        shouldThrow<AssertionError> { """{"a":1,"b":null,"c":0}""" shouldEqualJsonElement expected }
    }

    test("replaces a nested value and removes an array element") {
        val json = Json.parseToJsonElement("""{"a":[{"x":1},{"x":2}]}""")

        json.with("a.1.x", 3).toString() shouldEqualJsonElement Json.parseToJsonElement("""{"a":[{"x":1},{"x":3}]}""")
        json.without("a.0").toString() shouldEqualJsonElement Json.parseToJsonElement("""{"a":[{"x":2}]}""")
    }
})
