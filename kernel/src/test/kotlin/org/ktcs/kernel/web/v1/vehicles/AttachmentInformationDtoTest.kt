package org.ktcs.kernel.web.v1.vehicles

import io.kotest.core.spec.style.FunSpec
import org.ktcs.api.service.DriverAttachment
import org.ktcs.kernel.web.v1.GoldenJson
import org.ktcs.kernel.web.v1.GoldenJson.shouldEqualJsonElement
import org.ktcs.kernel.web.v1.V1Json

class AttachmentInformationDtoTest : FunSpec({
    test("encodes driver attachment information exactly as openTCS's sample") {
        val attachment = DriverAttachment(
            vehicle = "some-vehicle",
            availableDrivers = listOf(
                "com.example.somedriver.descriptionclass",
                "com.example.someotherdriver.descriptionclass",
            ),
            attachedDriver = "com.example.somedriver.descriptionclass",
            driverEnabled = true,
        )

        V1Json.json.encodeToString(AttachmentInformationDto.serializer(), attachment.toDto()) shouldEqualJsonElement
            GoldenJson.element("binding/GetVehicleAttachmentInfoResponseTOTest.jsonSample.approved.txt")
    }
})
