package org.ktcs.kernel.web.contract

import org.ktcs.kernel.web.contract.OpenApiContract.Violation

/**
 * The one place where a violation of openTCS's v1 specification is accepted: where the specification contradicts
 * the JSON openTCS itself sends, as its golden samples show. kTCS sends what openTCS sends, and kTCS's own document
 * describes that JSON (see its header), so these are checked there instead. `WebApiContractsTest` proves each entry
 * is still needed by a golden sample.
 */
object OpenTcsSpecDefects {
    /** A known defect: violations at an [at] pointer whose message contains [message]. */
    data class Defect(val reason: String, val at: Regex, val message: String) {
        fun excuses(violation: Violation): Boolean =
            violation.pointer != null && at.matches(violation.pointer) && message in violation.message
    }

    val all = listOf(
        Defect(
            "Status messages put additionalProperties: false beside allOf, which in JSON Schema rejects every property",
            Regex("/statusMessages/\\d+"),
            "",
        ),
        Defect(
            "openTCS writes null for every unset optional reference (its Jackson setup includes nulls; the golden " +
                "order sequence has processingVehicle null), but its schemas declare none of them nullable",
            anywhere("/(${UNSET_REFERENCES.joinToString("|")})"),
            "null found",
        ),
        Defect(
            "An unset deadline or finishedTime is Instant.MAX ($INSTANT_MAX), which is ISO 8601 but no RFC 3339 " +
                "date-time, as the golden order sequence shows",
            anywhere("/(deadline|finishedTime)"),
            "(was \"$INSTANT_MAX\")",
        ),
        Defect(
            "Plant model element properties are {name, value}, not the {key, value} of the referenced Property",
            Regex("/(points|paths|locations|locationTypes|blocks|vehicles)/\\d+/properties/\\d+"),
            "",
        ),
        Defect(
            "A location type's properties are an array like every other element's, not an object",
            Regex("/locationTypes/\\d+/properties"),
            "array found, object expected",
        ),
        Defect(
            "A vehicle envelope's key is called key, not envelopeKey",
            Regex("/(points|paths)/\\d+/vehicleEnvelopes/\\d+"),
            "required property 'envelopeKey' not found",
        ),
        Defect(
            "A drive order destination's properties are a {key, value} array, not an object",
            anywhere("/driveOrders/\\d+/destination/properties"),
            "array found, object expected",
        ),
        Defect(
            "A vehicle's acceptableOrderTypes items are {name, priority}, not the wrapper object AcceptableOrderTypes",
            anywhere("/acceptableOrderTypes/\\d+"),
            "required property 'acceptableOrderTypes' not found",
        ),
        Defect(
            "A route computation answer requires `Routes`, but the property is `routes`",
            Regex(""),
            "required property 'Routes' not found",
        ),
        Defect(
            "A computed route's steps are documented as `null` if no route was found, but not declared nullable",
            anywhere("/routes/\\d+/steps"),
            "null found",
        ),
        Defect(
            "An SSE vehicle's procState is {procState, timestamp}, not {state, timestamp}",
            anywhere("/procState"),
            "required property 'state' not found",
        ),
        Defect(
            "Jackson writes an unknown (NaN) orientation angle as the string \"NaN\", as openTCS's GET /vehicles " +
                "schema and golden sample allow, but the SSE vehicle pose allows only numbers",
            anywhere("/pose/orientationAngle"),
            "string found, number expected (was \"NaN\")",
        ),
    )

    private const val INSTANT_MAX = "+1000000000-12-31T23:59:59.999999999Z"

    /** The optional references of openTCS's transfer objects (`@Nullable` there); kTCS's document marks them so. */
    private val UNSET_REFERENCES
        get() = listOf(
            "transportOrder", "precisePosition", "currentPosition", "nextPosition", "orderSequence", "intendedVehicle",
            "processingVehicle", "wrappingSequence", "peripheralReservationToken", "processingVehicleName",
            "transportOrderName", "position", "previousObjectState", "currentObjectState", "envelopeKey",
        )

    /** [pointer] at the end of any JSON pointer: the same object appears alone, in lists and in other objects. */
    private fun anywhere(pointer: String) = Regex("(/[\\w/]+)?$pointer")

    /** The defect that excuses [violation], if any. */
    fun excusing(violation: Violation): Defect? = all.firstOrNull { it.excuses(violation) }

    /** [violations] without those the defects excuse. */
    fun unexcused(violations: List<Violation>): List<Violation> = violations.filter { excusing(it) == null }
}
