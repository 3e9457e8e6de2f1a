package org.ktcs.kernel.persistence

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.ktcs.api.model.BlockLayout
import org.ktcs.api.model.ConnectionType
import org.ktcs.api.model.Couple
import org.ktcs.api.model.LocationRepresentation
import org.ktcs.api.model.PlantModel
import org.ktcs.kernel.persistence.PersistenceFixtures.DEMO_5_0
import org.ktcs.kernel.persistence.PersistenceFixtures.DEMO_HEAD

/** openTCS's demo plant as shipped with 7.5 (7.0.0) and with 5.0 (0.0.3). */
class DemoModelsTest : FunSpec({
    fun demo(resource: String): PlantModel = PlantModelFiles.read(PersistenceFixtures.path(resource))

    test("the 7.5 demo loads completely") {
        demo(DEMO_HEAD).summary() shouldBe "points=59 paths=75 locations=16 locationTypes=4 blocks=2 vehicles=4"
    }

    test("the 5.0 demo loads completely") {
        demo(DEMO_5_0).summary() shouldBe "points=55 paths=68 locations=14 locationTypes=3 blocks=4 vehicles=4"
    }

    test("the 7.5 demo is written back as openTCS wrote it") {
        PlantModelFiles.writeToString(demo(DEMO_HEAD)) shouldBe PersistenceFixtures.text(DEMO_HEAD)
    }

    test("the 5.0 demo takes its layout from the model layout elements") {
        val model = demo(DEMO_5_0)
        val path = model.path("Point-0001 --- Point-0002")!!.layout
        path.connectionType shouldBe ConnectionType.BEZIER
        path.controlPoints shouldBe listOf(Couple(552, -183), Couple(552, -183))
        model.path("Point-0001 --- Point-0003")!!.layout.controlPoints shouldBe emptyList()
        model.point("Point-0001")!!.layout.labelOffset shouldBe Couple(-10, -20)
        model.block("Block-0004")!!.layout shouldBe BlockLayout("#FF3300")
        model.vehicles.map { it.layout.routeColor } shouldBe listOf("#FF0000", "#33FF00", "#00FFFF", "#FF33FF")
        model.locationType("Recharge station")!!.layout.locationRepresentation shouldBe
            LocationRepresentation.RECHARGE_GENERIC
        model.visualLayout.name shouldBe "VLayout-01"
    }
})
