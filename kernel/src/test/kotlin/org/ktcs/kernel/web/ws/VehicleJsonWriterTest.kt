package org.ktcs.kernel.web.ws

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.arbitrary.arbitrary
import io.kotest.property.arbitrary.boolean
import io.kotest.property.arbitrary.choice
import io.kotest.property.arbitrary.element
import io.kotest.property.arbitrary.enum
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.list
import io.kotest.property.arbitrary.long
import io.kotest.property.arbitrary.map
import io.kotest.property.arbitrary.numericDouble
import io.kotest.property.arbitrary.orNull
import io.kotest.property.arbitrary.set
import io.kotest.property.arbitrary.shuffle
import io.kotest.property.arbitrary.subsequence
import io.kotest.property.checkAll
import kotlinx.serialization.SerializationException
import kotlinx.serialization.descriptors.elementNames
import org.ktcs.api.model.AcceptableOrderType
import org.ktcs.api.model.BoundingBox
import org.ktcs.api.model.Couple
import org.ktcs.api.model.EnergyLevelThresholdSet
import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.model.LoadHandlingDevice
import org.ktcs.api.model.Position
import org.ktcs.api.model.ProcState
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleLayout
import org.ktcs.api.model.VehicleState
import org.ktcs.kernel.web.v1.V1Json
import org.ktcs.kernel.web.v1.events.SseVehicleDto
import org.ktcs.kernel.web.v1.events.toSseDto
import org.ktcs.kernel.web.ws.JsonArbs.shared

/**
 * The vehicle writer against the encoding it replaces: kotlinx's of the DTO, and fields cut from that by
 * [rewriteFields]. Compared as bytes (shown as Latin-1, one character per byte, so a failure shows every byte).
 */
class VehicleJsonWriterTest : FunSpec({
    fun kotlinx(vehicle: Vehicle) = utf8(V1Json.json.encodeToString(SseVehicleDto.serializer(), vehicle.toSseDto()))

    fun bytes(json: ByteArray) = String(json, Charsets.ISO_8859_1)

    // One for all vehicles, whose names and seldom changing objects repeat: kept values must be reused only for the
    // objects they were made of.
    val encoded = EncodedVehicles(4)
    val fieldNames = SseVehicleDto.serializer().descriptor.elementNames.toList()

    test("a vehicle is written byte for byte as kotlinx encodes its DTO") {
        checkAll(3000, VehicleArbs.vehicle) { vehicle ->
            val expected = runCatching { kotlinx(vehicle) }
            val marked = encoded.marked(vehicle)

            if (expected.isFailure) {
                // An infinite orientation, which kotlinx refuses to write.
                shouldThrow<SerializationException> { marked.full }
            } else {
                bytes(marked.full) shouldBe bytes(expected.getOrThrow())
            }
        }
    }

    test("a vehicle without some of its fields is what the byte scan cut from kotlinx's encoding") {
        val omitted = arbitrary { Arb.shuffle(Arb.subsequence(fieldNames + "noSuchField").bind()).bind() }

        checkAll(3000, VehicleArbs.writableVehicle, omitted) { vehicle, fields ->
            bytes(encoded.marked(vehicle).without(fields)) shouldBe bytes(rewriteFields(kotlinx(vehicle), fields))
        }
    }

    test("a string or a number is measured as long as it is written, so that a vehicle's array is made to size") {
        checkAll(3000, VehicleArbs.text, Arb.long()) { text, number ->
            Utf8JsonOut.sizeOf(text) shouldBe jsonString(text).size
            Utf8JsonOut.sizeOf(number) shouldBe number.toString().length
        }
    }

    test("the strings kotlinx escapes are escaped as it does, and a lone surrogate is a question mark") {
        val vehicle = Vehicle("q\"b\\s/\u0000\u001F\u007F\b\t\n\u000C\r\u2028é😀\uD83D.\uDE00")

        val name = bytes(encoded.marked(vehicle).without(fieldNames - "name"))

        val escaped = """{"name":"q\"b\\s/\u0000\u001f""" + "\u007F" + """\b\t\n\f\r""" + "\u2028é😀?.?\"}"
        name shouldBe bytes(utf8(escaped))
    }
})

/** Vehicles with anything their JSON can hold, their seldom changing objects often shared as copies share them. */
private object VehicleArbs {
    val text = JsonArbs.text
    private val instant = JsonArbs.instant

    // What kotlinx writes: NaN (as a string, see NanAsStringSerializer) and finite numbers.
    private val angle = Arb.choice(
        Arb.element(Double.NaN, 0.0, -0.0, Double.MIN_VALUE, Double.MAX_VALUE, 1e7, 1e-3, 1e-4, 90.0, -179.99),
        Arb.numericDouble(),
    )
    private val anyAngle = Arb.choice(angle, Arb.element(Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY))

    private val boundingBox = arbitrary {
        val offset = Couple(Arb.long().bind(), Arb.long().bind())
        BoundingBox(Arb.long().bind(), Arb.long().bind(), Arb.long().bind(), offset)
    }
    private val thresholds = arbitrary {
        EnergyLevelThresholdSet(Arb.int().bind(), Arb.int().bind(), Arb.int().bind(), Arb.int().bind())
    }
    private val layout = Arb.int(0..0xFFFFFF).map { rgb ->
        val digits = rgb.toString(HEX).padStart(COLOR_DIGITS, '0')
        VehicleLayout("#" + if (rgb % 2 == 0) digits.uppercase() else digits)
    }
    private val properties = Arb.map(text, text, 0, 5)
    private val orderTypes = Arb.set(arbitrary { AcceptableOrderType(text.bind(), Arb.int().bind()) }, 0..3)
    private val devices = Arb.list(arbitrary { LoadHandlingDevice(text.bind(), Arb.boolean().bind()) }, 0..3)
    private val position = arbitrary { Position(Arb.long().bind(), Arb.long().bind(), Arb.long().bind()) }

    // Steps made of shared sets, so that a list is now and then the end of one written before.
    private val resources = Arb.list(shared(Arb.set(text, 0..3), poolSize = 6), 0..4)

    fun vehicle(orientation: Arb<Double>) = arbitrary {
        Vehicle(
            name = shared(text).bind(),
            energyLevelThresholdSet = shared(thresholds).bind(),
            maxVelocity = Arb.int().bind(),
            maxReverseVelocity = Arb.int().bind(),
            boundingBox = shared(boundingBox).bind(),
            envelopeKey = text.orNull(NULLS).bind(),
            layout = shared(layout).bind(),
            properties = shared(properties).bind(),
            energyLevel = Arb.int().bind(),
            state = Arb.enum<VehicleState>().bind(),
            stateTimestamp = shared(instant).bind(),
            procState = Arb.enum<ProcState>().bind(),
            procStateTimestamp = shared(instant).bind(),
            integrationLevel = Arb.enum<IntegrationLevel>().bind(),
            paused = Arb.boolean().bind(),
            currentPosition = text.orNull(NULLS).bind(),
            precisePosition = position.orNull(NULLS).bind(),
            orientationAngle = orientation.bind(),
            transportOrder = text.orNull(NULLS).bind(),
            orderSequence = text.orNull(NULLS).bind(),
            allocatedResources = resources.bind(),
            claimedResources = resources.bind(),
            acceptableOrderTypes = shared(orderTypes).bind(),
            loadHandlingDevices = shared(devices).bind(),
            rechargeOperation = text.bind(),
            waitingReason = text.orNull(NULLS).bind(),
        )
    }

    val vehicle = vehicle(anyAngle)
    val writableVehicle = vehicle(angle)

    private const val NULLS = 0.3
    private const val HEX = 16
    private const val COLOR_DIGITS = 6
}
