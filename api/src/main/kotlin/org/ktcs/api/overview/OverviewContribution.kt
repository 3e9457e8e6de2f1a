package org.ktcs.api.overview

/**
 * Something an extension adds to the browser plant overview: an ES module that the page loads from the kernel
 * application. Bind instances in the extension's Koin module with the type `OverviewContribution`, e.g.
 * `single<OverviewContribution>(named("my-panel")) { OverviewPanel(...) }`; the overview lists every one.
 *
 * The kernel application serves the class-path resources below [resourceDirectory], as seen by [classLoader], at
 * `/overview/extensions/{name}/`, and the page imports `/overview/extensions/{name}/{entryModule}`. Keep every file
 * the module needs (further modules, styles, images) in that directory and import them relatively.
 */
public sealed class OverviewContribution(
    /** Unique among all contributions; lower-case letters, digits and dashes, as it appears in URLs. */
    public val name: String,
    /** What the page shows to the operator. */
    public val title: String,
    /** The class-path directory holding the front-end files, e.g. `org/example/overview`. */
    public val resourceDirectory: String,
    /** The ES module inside [resourceDirectory] that the page imports. */
    public val entryModule: String,
    /** The class loader that sees [resourceDirectory]; pass the extension's own (`javaClass.classLoader`). */
    public val classLoader: ClassLoader,
) {
    init {
        require(NAME.matches(name)) { "overview contribution name '$name' must match ${NAME.pattern}" }
        require(title.isNotBlank()) { "overview contribution '$name' needs a title" }
        require(!entryModule.startsWith("/") && ".." !in entryModule) {
            "entry module '$entryModule' of overview contribution '$name' must be a path inside its resource directory"
        }
    }

    override fun toString(): String = "${javaClass.simpleName}($name)"

    private companion object {
        val NAME = Regex("[a-z0-9]+(-[a-z0-9]+)*")
    }
}

/**
 * A panel of the browser overview, e.g. a load generator or statistics. Its entry module's default export is an
 * object with `mount(container, ktcs)`; the contract of `ktcs` (API calls, live topics) is in `web-overview/README.md`.
 */
public class OverviewPanel(
    name: String,
    title: String,
    resourceDirectory: String,
    entryModule: String = "panel.js",
    classLoader: ClassLoader,
) : OverviewContribution(name, title, resourceDirectory, entryModule, classLoader)

/**
 * A theme that decides how the overview draws [target]s. The configuration (`overview.vehicleTheme`,
 * `overview.locationTheme`) selects one theme by name for each target.
 */
public class OverviewTheme(
    name: String,
    title: String,
    /** What this theme draws. */
    public val target: ThemeTarget,
    resourceDirectory: String,
    entryModule: String = "theme.js",
    classLoader: ClassLoader,
) : OverviewContribution(name, title, resourceDirectory, entryModule, classLoader)

/** What an [OverviewTheme] draws. */
public enum class ThemeTarget {
    VEHICLES,
    LOCATIONS,
}
