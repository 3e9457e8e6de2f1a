package org.ktcs.kernel.app

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.datatest.withData
import io.kotest.engine.spec.tempfile
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldNotBeEmpty
import io.kotest.matchers.ints.shouldBeGreaterThanOrEqual
import io.kotest.matchers.nulls.shouldNotBeNull
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import org.ktcs.api.model.PointType
import org.ktcs.kernel.persistence.PersistenceFixtures
import org.ktcs.kernel.validation.InvalidModelException
import java.nio.file.Files

class PlantModelLoaderTest : FunSpec({
    context("every openTCS model fixture loads") {
        withData(PersistenceFixtures.openTcsModels) { resource ->
            val loaded = PlantModelLoader.load(PersistenceFixtures.path(resource))
            loaded.model.points.shouldNotBeEmpty()
            loaded.source shouldContain resource.substringAfterLast('/')
        }
    }

    test("the demo plant has vehicles, load/unload and recharge stations and parking positions, without warnings") {
        val loaded = PlantModelLoader.loadDemo()
        val model = loaded.model
        loaded.warnings.shouldBeEmpty()
        model.vehicles.size shouldBeGreaterThanOrEqual 4
        model.vehicles.map { it.properties["loopback:initialPosition"] }.forEach { start ->
            start.shouldNotBeNull()
            model.point(start).shouldNotBeNull()
        }
        val operations = model.locations.flatMap { model.locationType(it.type)!!.allowedOperations }.toSet()
        operations.containsAll(setOf("Load cargo", "Unload cargo", "CHARGE")) shouldBe true
        model.points.count { it.type == PointType.PARK_POSITION } shouldBe 5
    }

    test("a model with errors is refused as a whole") {
        val broken = tempfile("broken", ".xml").toPath()
        Files.writeString(
            broken,
            PersistenceFixtures.text(
                PersistenceFixtures.DEMO_HEAD,
            ).replace("type=\"Recharge station\"", "type=\"Nope\""),
        )
        shouldThrow<InvalidModelException> {
            PlantModelLoader.load(broken)
        }.problems.first { it.isError }.message shouldContain
            "Nope"
    }
})
