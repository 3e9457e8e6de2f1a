package org.ktcs.kernel.persistence

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import org.ktcs.api.model.BlockLayout
import org.ktcs.api.model.ConnectionType
import org.ktcs.api.model.Couple
import org.ktcs.api.model.LocationRepresentation
import org.ktcs.api.model.PlantModel
import org.ktcs.kernel.persistence.PersistenceFixtures.DEMO_5_0
import org.ktcs.kernel.persistence.PersistenceFixtures.DEMO_HEAD
import kotlin.math.hypot

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

    test("the 5.0 demo's points are drawn where openTCS drew them, with a warning naming the discrepancy") {
        val read = PlantModelFiles.readWithWarnings(PersistenceFixtures.path(DEMO_5_0))
        val point = read.model.point("Point-0001")!!.pose.position
        (point.x to point.y) shouldBe (28000L to 11000L)
        read.model.location("Goods in north 01")!!.position.x shouldBe -28000
        read.warnings.map { it.message }.single { "drawn" in it } shouldContain
            "point 'Point-0001' model (53288,-3893) drawn (28000,11000)"
    }

    test("the 5.0 demo's paths join their points: every control point lies near its path's ends") {
        val model = demo(DEMO_5_0)
        val scale = model.visualLayout.scaleX
        model.paths.filter { it.layout.controlPoints.isNotEmpty() }.forEach { path ->
            val ends = listOf(path.sourcePoint, path.destinationPoint).map { model.point(it)!!.pose.position }
            path.layout.controlPoints.forEach { control ->
                val distance = ends.minOf { hypot(control.x * scale - it.x, -control.y * scale - it.y) }
                withClue(path.name) { (distance < 10_000.0) shouldBe true }
            }
        }
    }

    test("the 7.5 demo reads without warnings") {
        PlantModelFiles.readWithWarnings(PersistenceFixtures.path(DEMO_HEAD)).warnings shouldBe emptyList()
    }
})
