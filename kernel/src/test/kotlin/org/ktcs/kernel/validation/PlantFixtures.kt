package org.ktcs.kernel.validation

import org.ktcs.api.model.Block
import org.ktcs.api.model.Link
import org.ktcs.api.model.Location
import org.ktcs.api.model.LocationType
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point
import org.ktcs.api.model.Vehicle

/** Two points joined by one path, a location linked to the first point, a vehicle and a block: no problems at all. */
fun minimalPlant(): PlantModel = PlantModel(
    name = "minimal",
    points = listOf(Point("A"), Point("B")),
    paths = listOf(Path("A --- B", sourcePoint = "A", destinationPoint = "B", length = 1000)),
    locationTypes = listOf(LocationType("Transfer", allowedOperations = setOf("LOAD", "UNLOAD"))),
    locations = listOf(Location("Station", type = "Transfer", links = listOf(Link("A", setOf("LOAD"))))),
    vehicles = listOf(Vehicle("Vehicle-01")),
    blocks = listOf(Block("Block-01", members = setOf("A", "A --- B", "Station"))),
)

fun PlantModel.mapPoints(change: (Point) -> Point) = copy(points = points.map(change))

fun PlantModel.mapPaths(change: (Path) -> Path) = copy(paths = paths.map(change))

fun PlantModel.mapLocationTypes(change: (LocationType) -> LocationType) = copy(
    locationTypes = locationTypes.map(change),
)

fun PlantModel.mapLocations(change: (Location) -> Location) = copy(locations = locations.map(change))

fun PlantModel.mapVehicles(change: (Vehicle) -> Vehicle) = copy(vehicles = vehicles.map(change))

fun PlantModel.mapBlocks(change: (Block) -> Block) = copy(blocks = blocks.map(change))

fun PlantModel.problems(): List<ModelProblem> = PlantModelValidator.validate(this)

fun PlantModel.errors(): List<ModelProblem> = problems().filter { it.isError }

fun PlantModel.warnings(): List<ModelProblem> = problems().filterNot { it.isError }

fun expectedError(element: String, message: String) = ModelProblem(Severity.ERROR, element, message)

fun expectedWarning(element: String, message: String) = ModelProblem(Severity.WARNING, element, message)
