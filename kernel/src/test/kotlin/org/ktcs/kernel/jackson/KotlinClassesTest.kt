package org.ktcs.kernel.jackson

import com.fasterxml.jackson.databind.exc.MismatchedInputException
import com.fasterxml.jackson.databind.json.JsonMapper
import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import org.ktcs.api.order.OrderSequence
import org.ktcs.kernel.store.StateCodec
import java.time.Instant

internal data class WithDefaults(
    val name: String,
    val index: Int = -1,
    val types: Set<String> = setOf("*"),
    val note: String? = "none",
    val items: List<String> = emptyList(),
)

internal data class NoDefaults(val name: String, val count: Int)

internal data class AllDefaults(val kind: String = "a", val size: Int = 3)

internal data class Outer(val inner: List<NoDefaults>)

/** Jackson without kotlin-reflect binds Kotlin classes as jackson-module-kotlin did: defaults, missing values, nulls. */
class KotlinClassesTest : FunSpec({
    val mapper = KotlinClasses.configure(JsonMapper.builder()).build()

    fun <T> read(json: String, type: Class<T>): T = mapper.readValue(json, type)

    test("a value left out takes the parameter's Kotlin default, however non-trivial") {
        read("""{"name":"n"}""", WithDefaults::class.java) shouldBe WithDefaults("n")
        read("""{"name":"n","index":4}""", WithDefaults::class.java) shouldBe WithDefaults("n", index = 4)
        read("""{"size":5}""", AllDefaults::class.java) shouldBe AllDefaults(size = 5)
    }

    test("a null for a nullable parameter stays null; a null list, set or map is empty") {
        read("""{"name":"n","note":null,"items":null,"types":null}""", WithDefaults::class.java) shouldBe
            WithDefaults("n", types = emptySet(), note = null)
    }

    test("a required value left out or null is an error that names it, also a number without default") {
        fun failure(json: String) = shouldThrow<MismatchedInputException> { read(json, NoDefaults::class.java) }

        failure("""{"count":1}""").message shouldContain "missing required value 'name'"
        failure("""{"name":null,"count":1}""").message shouldContain "missing required value 'name'"
        failure("""{"name":"n"}""").path.map { it.fieldName } shouldBe listOf("count")
        val nested = shouldThrow<MismatchedInputException> {
            read("""{"inner":[{"name":"a","count":1},{"count":2}]}""", Outer::class.java)
        }
        nested.path.map { it.fieldName ?: it.index.toString() } shouldBe listOf("inner", "1", "name")
    }

    test("a stored order sequence written without its defaulted fields reads back with the api's defaults") {
        val created = Instant.ofEpochSecond(1_700_000_000, 5)
        StateCodec.sequence("""{"name":"Sequence-1","creationTime":"1700000000:5"}""") shouldBe
            OrderSequence("Sequence-1", created)
        val sequence = OrderSequence("Sequence-2", created, orders = listOf("Order-1"), finishedIndex = 0)
        StateCodec.sequence(StateCodec.write(sequence)) shouldBe sequence
    }
})
