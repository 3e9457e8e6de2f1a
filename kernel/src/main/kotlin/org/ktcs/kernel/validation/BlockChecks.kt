package org.ktcs.kernel.validation

import org.ktcs.api.model.Block

internal fun blockProblems(index: ModelIndex): List<ModelProblem> =
    index.model.blocks.flatMap { blockProblems(it, index) }

private fun blockProblems(block: Block, index: ModelIndex): List<ModelProblem> =
    listOfNotNull(block.warningIf(block.members.isEmpty()) { "has no members" }) +
        block.members.mapNotNull { member ->
            block.errorIf(!index.isBlockable(member)) { "member '$member' names no point, path or location" }
        }
