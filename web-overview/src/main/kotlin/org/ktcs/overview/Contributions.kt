package org.ktcs.overview

import org.ktcs.api.overview.OverviewContribution
import org.ktcs.api.overview.OverviewPanel
import org.ktcs.api.overview.OverviewTheme
import org.ktcs.api.overview.ThemeTarget
import org.ktcs.extension.ExtensionException

/** Every panel and theme of every extension, by name; two with the same name stop the start. */
class Contributions(all: List<OverviewContribution>) {
    val all: List<OverviewContribution> = all.sortedWith(compareBy({ it !is OverviewPanel }, { it.name }))

    private val byName: Map<String, OverviewContribution> = all.groupBy { it.name }.mapValues { (name, same) ->
        if (same.size > 1) {
            throw ExtensionException("overview contributions share the name '$name': ${same.joinToString()}")
        }
        same.single()
    }

    operator fun get(name: String): OverviewContribution? = byName[name]

    fun themes(target: ThemeTarget): List<OverviewTheme> =
        all.filterIsInstance<OverviewTheme>().filter { it.target == target }

    /** The listing of `/overview/extensions.json`. */
    fun listing(): List<ContributionEntry> = all.map { contribution ->
        ContributionEntry(
            kind = if (contribution is OverviewPanel) "panel" else "theme",
            name = contribution.name,
            title = contribution.title,
            target = (contribution as? OverviewTheme)?.target?.name,
            module = "/overview/extensions/${contribution.name}/${contribution.entryModule}",
        )
    }
}

@kotlinx.serialization.Serializable
data class ContributionEntry(
    val kind: String,
    val name: String,
    val title: String,
    val target: String?,
    val module: String,
)
