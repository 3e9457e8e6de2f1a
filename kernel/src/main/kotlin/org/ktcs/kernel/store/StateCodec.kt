package org.ktcs.kernel.store

import com.fasterxml.jackson.annotation.JsonAutoDetect
import com.fasterxml.jackson.annotation.PropertyAccessor
import com.fasterxml.jackson.core.JsonGenerator
import com.fasterxml.jackson.core.JsonParser
import com.fasterxml.jackson.core.JsonToken
import com.fasterxml.jackson.databind.DeserializationContext
import com.fasterxml.jackson.databind.DeserializationFeature
import com.fasterxml.jackson.databind.JsonDeserializer
import com.fasterxml.jackson.databind.JsonSerializer
import com.fasterxml.jackson.databind.MapperFeature
import com.fasterxml.jackson.databind.ObjectMapper
import com.fasterxml.jackson.databind.SerializerProvider
import com.fasterxml.jackson.databind.json.JsonMapper
import com.fasterxml.jackson.databind.module.SimpleModule
import org.ktcs.api.event.UserNotification
import org.ktcs.api.order.OrderSequence
import org.ktcs.api.order.Step
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.VehicleOrientation
import org.ktcs.kernel.jackson.KotlinClasses
import java.time.Instant
import java.util.concurrent.ConcurrentHashMap

/**
 * The JSON form of the stored objects. Instants are written as `seconds:nanos`, which holds every instant exactly
 * (an order without deadline has [Instant.MAX]); only fields are written, computed properties are not.
 */
object StateCodec {
    private val mapper: ObjectMapper = KotlinClasses.configure(JsonMapper.builder())
        .addModule(
            SimpleModule()
                .addSerializer(Instant::class.java, InstantWriter)
                .addDeserializer(Instant::class.java, InstantReader)
                .addSerializer(Step::class.java, StepWriter)
                .addDeserializer(Step::class.java, StepReader),
        )
        // Only what the objects hold, not what they compute (an order's current drive order would be written twice).
        .visibility(PropertyAccessor.ALL, JsonAutoDetect.Visibility.NONE)
        .visibility(PropertyAccessor.FIELD, JsonAutoDetect.Visibility.ANY)
        .disable(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES)
        .enable(MapperFeature.SORT_PROPERTIES_ALPHABETICALLY)
        .build()

    private val orderWriter = TransportOrderWriter(mapper.factory)

    fun write(value: Any): String = if (value is TransportOrder) orderWriter.write(value) else jackson(value)

    /** What Jackson writes for [value]: the form [TransportOrderWriter] writes by hand (compared in StateCodecTest). */
    internal fun jackson(value: Any): String = mapper.writeValueAsString(value)

    fun <T> read(json: String, type: Class<T>): T = mapper.readValue(json, type)

    private val singleOrders = TransportOrderReader.single(mapper.factory)

    fun order(json: String): TransportOrder = singleOrders.read(json)

    /** Reads the orders of a store, on any number of threads; equal routes come back as one instance. */
    fun orders(): (String) -> TransportOrder = TransportOrderReader.sharingRoutes(mapper.factory)::read

    fun sequence(json: String): OrderSequence = read(json, OrderSequence::class.java)

    fun vehicle(json: String): StoredVehicle = read(json, StoredVehicle::class.java)

    fun lock(json: String): StoredLock = read(json, StoredLock::class.java)

    fun notification(json: String): UserNotification = read(json, UserNotification::class.java)

    fun names(json: String): NamePosition = read(json, NamePosition::class.java)

    private object InstantWriter : JsonSerializer<Instant>() {
        override fun serialize(value: Instant, generator: JsonGenerator, serializers: SerializerProvider) =
            generator.writeString(instant(value))
    }

    // The names of the plant's points, paths and vehicles, of order types and history codes (all bounded sets), one
    // instance each: 100,000 stored orders repeat them millions of times.
    private val plantNames = ConcurrentHashMap<String, String>()

    internal fun shared(name: String): String = plantNames.putIfAbsent(name, name) ?: name

    // A route step as a six-element array: routes are most of a stored order, and a restart reads 100,000 of them.
    private object StepWriter : JsonSerializer<Step>() {
        override fun serialize(value: Step, generator: JsonGenerator, serializers: SerializerProvider) =
            step(generator, value)
    }

    /** Writes [step] as a six-element array. */
    internal fun step(generator: JsonGenerator, step: Step) {
        generator.writeStartArray()
        generator.writeString(step.path)
        generator.writeString(step.sourcePoint)
        generator.writeString(step.destinationPoint)
        generator.writeString(step.vehicleOrientation.name)
        generator.writeNumber(step.routeIndex)
        generator.writeBoolean(step.executionAllowed)
        generator.writeEndArray()
    }

    private object StepReader : JsonDeserializer<Step>() {
        override fun deserialize(parser: JsonParser, context: DeserializationContext): Step = step(parser)
    }

    /** A route step as [StepWriter] writes it, the parser on its array. */
    internal fun step(parser: JsonParser): Step {
        check(parser.isExpectedStartArrayToken) { "a route step must be an array" }
        val path = parser.nextTextValue()?.let(::shared)
        val source = parser.nextTextValue()?.let(::shared)
        val destination = shared(checkNotNull(parser.nextTextValue()) { "a route step needs a destination point" })
        val orientation = VehicleOrientation.valueOf(parser.nextTextValue())
        parser.nextToken()
        val routeIndex = parser.intValue
        parser.nextToken()
        val executionAllowed = parser.booleanValue
        check(parser.nextToken() == JsonToken.END_ARRAY) { "a route step has six elements" }
        return Step(path, source, destination, orientation, routeIndex, executionAllowed)
    }

    private object InstantReader : JsonDeserializer<Instant>() {
        override fun deserialize(parser: JsonParser, context: DeserializationContext): Instant =
            instant(parser.valueAsString)
    }

    /** [instant] as `seconds:nanos`. */
    internal fun instant(instant: Instant): String = "${instant.epochSecond}:${instant.nano}"

    /** An instant as [InstantWriter] writes it, `seconds:nanos`. */
    internal fun instant(text: String): Instant {
        val colon = text.indexOf(':')
        require(colon > 0) { "an instant is written as seconds:nanos, not '$text'" }
        return Instant.ofEpochSecond(text.substring(0, colon).toLong(), text.substring(colon + 1).toLong())
    }
}
