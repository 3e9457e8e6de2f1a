// The Gradle build mirrors the Maven reactor (pom.xml): same modules, same versions (gradle/libs.versions.toml),
// same dependencies per module. Maven is the build CI runs; BuildFilesAgreeTest keeps this one in step.
rootProject.name = "ktcs"

dependencyResolutionManagement {
    repositoriesMode.set(RepositoriesMode.FAIL_ON_PROJECT_REPOS)
    repositories {
        mavenCentral()
    }
}

include(
    "api",
    "extension-api",
    "kernel",
    "adapters-loopback",
    "web-overview",
    "xml-channels",
    "adapters-vda5050",
    "vda5050-tools",
    "examples:tcp-vehicle-driver",
    "examples:nearest-vehicle-dispatcher",
    "examples:overview-panel-theme",
    "examples:kotlin-clients",
    "e2e-tests",
)
