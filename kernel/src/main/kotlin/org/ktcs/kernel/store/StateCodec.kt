package org.ktcs.kernel.store

import com.fasterxml.jackson.core.JsonGenerator
import com.fasterxml.jackson.core.JsonParser
import com.fasterxml.jackson.databind.DeserializationContext
import com.fasterxml.jackson.databind.DeserializationFeature
import com.fasterxml.jackson.databind.JsonDeserializer
import com.fasterxml.jackson.databind.JsonSerializer
import com.fasterxml.jackson.databind.MapperFeature
import com.fasterxml.jackson.databind.ObjectMapper
import com.fasterxml.jackson.databind.SerializerProvider
import com.fasterxml.jackson.databind.json.JsonMapper
import com.fasterxml.jackson.databind.module.SimpleModule
import com.fasterxml.jackson.module.kotlin.kotlinModule
import org.ktcs.api.event.UserNotification
import org.ktcs.api.order.OrderSequence
import org.ktcs.api.order.TransportOrder
import java.time.Instant

/**
 * The JSON form of the stored objects. Instants are written as `seconds:nanos`, which holds every instant exactly
 * (an order without deadline has [Instant.MAX]); computed properties are written but ignored when read.
 */
object StateCodec {
    private val mapper: ObjectMapper = JsonMapper.builder()
        .addModule(kotlinModule())
        .addModule(SimpleModule().addSerializer(Instant::class.java, InstantWriter).addDeserializer(Instant::class.java, InstantReader))
        .disable(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES)
        .enable(MapperFeature.SORT_PROPERTIES_ALPHABETICALLY)
        .build()

    fun write(value: Any): String = mapper.writeValueAsString(value)

    fun <T> read(json: String, type: Class<T>): T = mapper.readValue(json, type)

    fun order(json: String): TransportOrder = read(json, TransportOrder::class.java)

    fun sequence(json: String): OrderSequence = read(json, OrderSequence::class.java)

    fun vehicle(json: String): StoredVehicle = read(json, StoredVehicle::class.java)

    fun lock(json: String): StoredLock = read(json, StoredLock::class.java)

    fun notification(json: String): UserNotification = read(json, UserNotification::class.java)

    fun names(json: String): NamePosition = read(json, NamePosition::class.java)

    private object InstantWriter : JsonSerializer<Instant>() {
        override fun serialize(value: Instant, generator: JsonGenerator, serializers: SerializerProvider) =
            generator.writeString("${value.epochSecond}:${value.nano}")
    }

    private object InstantReader : JsonDeserializer<Instant>() {
        override fun deserialize(parser: JsonParser, context: DeserializationContext): Instant {
            val (seconds, nanos) = parser.valueAsString.split(':').map(String::toLong)
            return Instant.ofEpochSecond(seconds, nanos)
        }
    }
}
