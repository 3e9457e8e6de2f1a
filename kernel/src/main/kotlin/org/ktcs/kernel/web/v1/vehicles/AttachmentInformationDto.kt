package org.ktcs.kernel.web.v1.vehicles

import kotlinx.serialization.Serializable
import org.ktcs.api.service.DriverAttachment

/**
 * The answer of `GET /vehicles/{NAME}/commAdapter/attachmentInformation`. kTCS names drivers by factory name where
 * openTCS writes a driver description class; a vehicle without a driver gets `null`.
 */
@Serializable
data class AttachmentInformationDto(
    val vehicleName: String,
    val availableCommAdapters: List<String>,
    val attachedCommAdapter: String?,
)

fun DriverAttachment.toDto(): AttachmentInformationDto =
    AttachmentInformationDto(vehicle, availableDrivers, attachedDriver)
