package org.ktcs.adapters.vda5050.protocol

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldHaveSize
import io.kotest.matchers.shouldBe
import io.kotest.matchers.shouldNotBe

private fun ByteArray.slices(name: String) = StateScan.Splitting(setOf(name)).scan(this).arrays.getValue(name).elements

private fun String.scanned(kept: Map<String, List<Int>>) =
    String(
        StateScan.Splitting(kept.keys).scan(toByteArray()).let {
            it.withOnly(it.fields.orEmpty(), kept, toByteArray())
        },
    )

/** A state message's top level and arrays, found without a tree, spelt exactly as sent. */
class StateScanTest : FunSpec({
    test("fields and elements keep their bytes, white space, escapes and nesting included") {
        val message =
            """ { "a" : 1 , "nodeStates" : [ {"x": "],[{\"}"} ,{"y":[1,{"z":[]}]}, 2.5e3 , "s" ] ,"b":{"c":[3]} } """
        val scan = StateScan.Splitting(setOf("nodeStates")).scan(message.toByteArray())
        String(scan.withOnly(scan.fields!!, emptyMap(), byteArrayOf())) shouldBe """{"a" : 1,"b":{"c":[3]}}"""
        scan.fields!!.map { it.name.toString() } shouldBe listOf("\"a\"", "\"b\"")
        String(scan.withOnly(scan.fields!!.drop(1), emptyMap(), byteArrayOf())) shouldBe """{"b":{"c":[3]}}"""
        message.scanned(mapOf("nodeStates" to listOf(3, 0, 2))) shouldBe
            """{"a" : 1,"b":{"c":[3]},"nodeStates":["s",{"x": "],[{\"}"},2.5e3]}"""
        message.scanned(mapOf("nodeStates" to listOf(1))) shouldBe
            """{"a" : 1,"b":{"c":[3]},"nodeStates":[{"y":[1,{"z":[]}]}]}"""
    }

    test("equal elements are found by their bytes wherever they stand") {
        val first = """{"nodeStates":[{"n":1},{"n":2},{"n":3}]}""".toByteArray().slices("nodeStates")
        val second = """{"headerId":7,"nodeStates":[{"n":2}, {"n":3},{"n":4}]}""".toByteArray().slices("nodeStates")
        second[0] shouldBe first[1]
        second[1] shouldBe first[2]
        second[2] shouldNotBe first[0]
        second.toSet().intersect(first.toSet()) shouldHaveSize 2
        // The same content spelt otherwise is another element: it is read again, never taken for a known one.
        """{"nodeStates":[{"n": 1}]}""".toByteArray().slices("nodeStates").single() shouldNotBe first[0]
    }

    test("what is not one JSON object is left whole, for the tree parser to name what is wrong") {
        listOf("""[1,2]""", """{"a":1} {"b":2}""", """{"a":""", """"text"""", """{"nodeStates":[1,}""").forEach {
            it.scanned(mapOf("nodeStates" to emptyList())) shouldBe it
        }
    }
})
