package org.ktcs.kernel.web.ws

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.types.shouldBeSameInstanceAs
import kotlinx.serialization.builtins.ListSerializer
import kotlinx.serialization.builtins.SetSerializer
import kotlinx.serialization.builtins.serializer
import org.ktcs.kernel.web.v1.V1Json

class EncodedResourceListsTest : FunSpec({
    val steps = listOf(setOf("Punkt-Ä"), setOf("Ä --- \"B\"", "B"), setOf("B --- C", "C"), setOf("C --- D", "D"))

    fun serialized(list: List<Set<String>>) =
        V1Json.json.encodeToString(ListSerializer(SetSerializer(String.serializer())), list)

    test("a list and each end of it are the JSON the serializer writes") {
        val lists = EncodedResourceLists(4)

        lists.of("V1", steps).decodeToString() shouldBe serialized(steps)
        for (skipped in 1..steps.size) {
            val rest = steps.drop(skipped)
            lists.of("V1", rest).decodeToString() shouldBe serialized(rest)
        }
    }

    test("the same list is not encoded again; a list whose steps changed is") {
        val lists = EncodedResourceLists(4)
        val first = lists.of("V1", steps)

        lists.of("V1", steps) shouldBeSameInstanceAs first
        val rerouted = listOf(steps[0], setOf("A --- X", "X"), steps[2])
        lists.of("V1", rerouted).decodeToString() shouldBe serialized(rerouted)
        // Equal sets that are other objects: encoded anew, with the same result.
        val copied = steps.drop(2).map { it.toSet() }
        lists.of("V1", copied).decodeToString() shouldBe serialized(copied)
    }

    test("each vehicle's list is kept apart from the others'") {
        val lists = EncodedResourceLists(4)
        lists.of("V1", steps)
        lists.of("V2", steps.take(1))

        lists.of("V1", steps.drop(1)).decodeToString() shouldBe serialized(steps.drop(1))
        lists.of("V2", emptyList()).decodeToString() shouldBe "[]"
    }
})
