package org.ktcs.kernel.web.v1.vehicles

import kotlinx.serialization.Serializable
import org.ktcs.api.driver.DriverMessage
import org.ktcs.api.model.AcceptableOrderType
import org.ktcs.api.model.EnergyLevelThresholdSet
import org.ktcs.kernel.web.v1.AcceptableOrderTypeDto
import org.ktcs.kernel.web.v1.PropertyDto
import org.ktcs.kernel.web.v1.requirePercent
import org.ktcs.kernel.web.v1.required
import org.ktcs.kernel.web.v1.toDomain

/** The body of `PUT /vehicles/{NAME}/allowedOrderTypes`. */
@Serializable
data class PutAllowedOrderTypesRequest(val orderTypes: List<String>? = null)

fun PutAllowedOrderTypesRequest.toDomain(): Set<String> = orderTypes.required("orderTypes").toSet()

/** The body of `PUT /vehicles/{NAME}/acceptableOrderTypes`. */
@Serializable
data class PutAcceptableOrderTypesRequest(val acceptableOrderTypes: List<AcceptableOrderTypeDto>? = null)

fun PutAcceptableOrderTypesRequest.toDomain(): Set<AcceptableOrderType> =
    acceptableOrderTypes.required("acceptableOrderTypes").mapIndexed { i, type ->
        AcceptableOrderType(
            type.name.required("acceptableOrderTypes[$i].name"),
            type.priority.required("acceptableOrderTypes[$i].priority"),
        )
    }.toSet()

/** The body of `PUT /vehicles/{NAME}/energyLevelThresholdSet`; every level is a percentage. */
@Serializable
data class PutEnergyLevelThresholdSetRequest(
    val energyLevelCritical: Int? = null,
    val energyLevelGood: Int? = null,
    val energyLevelSufficientlyRecharged: Int? = null,
    val energyLevelFullyRecharged: Int? = null,
)

fun PutEnergyLevelThresholdSetRequest.toDomain(): EnergyLevelThresholdSet = EnergyLevelThresholdSet(
    critical = percent(energyLevelCritical, "energyLevelCritical"),
    good = percent(energyLevelGood, "energyLevelGood"),
    sufficientlyRecharged = percent(energyLevelSufficientlyRecharged, "energyLevelSufficientlyRecharged"),
    fullyRecharged = percent(energyLevelFullyRecharged, "energyLevelFullyRecharged"),
)

private fun percent(value: Int?, field: String) = requirePercent(value.required(field), field)

/** The body of `POST /vehicles/{NAME}/commAdapter/message`. */
@Serializable
data class PostCommAdapterMessageRequest(val type: String? = null, val parameters: List<PropertyDto>? = null)

fun PostCommAdapterMessageRequest.toDomain(): DriverMessage =
    DriverMessage(type.required("type"), parameters.required("parameters").toDomain("parameters"))
