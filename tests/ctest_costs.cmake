# SPDX-License-Identifier: MIT
# Run time of the longest tests, in seconds on two cores, for ctest's scheduler. ctest starts the
# longest tests first once it has timed them (Testing/Temporary/CTestCostData.txt); a fresh build
# has no such record, so without these figures the minutes-long end-to-end tests, declared last,
# would start last and run alone while the other core idles (CI builds afresh every time).
# Included by ctest after the discovered tests (tests added with add_test in tests/CMakeLists.txt
# set their COST there); Ctest.CostsNameExistingTests checks that every name is a test.
set(demwb_test_costs
  "DemwbSuite.CanonicalSuitePassesTheGateWithOneReportCoveringEveryCaseThatPandocRendersCleanly=300"
  "PayloadCorpus.NoPayloadInAnyStringRunsACommandOrChangesARun=80"
  "DemwbFuzzMatched.TwentyYadeScenesAgreeOrAreNotApplicable=28"
  "FakeLammps.EveryFaultIsAnErrorThatFailsTheRun=5"
  "DemwbFuzzMatched.TwentyLammpsScenesAgreeOrAreNotApplicable=21"
  "Reproducible.TwoFreshRunsWriteIdenticalResults=20"
  "Refresh.AFolderOfCasesExitsZeroWithItsNotApplicableRows=20"
  "FakeYade.EveryFaultIsAnErrorThatFailsTheRun=7"
  "Cache.ATamperedEntryIsDetectedRunAgainAndReplaced=5"
  "LammpsPhase2.TsujiMapsOverTheWholeRestitutionRangeUpToTheUndampedOne=16"
  "DemwbSuite.ASecondRunReusesCachedReferenceResultsAndWritesIdenticalResults=13"
  "Tiers.AFullTierCaseInTheFastTierComparesAgainstItsBaselineWhileItFitsCaseAndDeck=12"
  "DemwbRun.SameCaseTwiceGivesBitIdenticalTraces=11"
  "DemwbCompare.PrintsTheTableAndPassesOnTheCanonicalCases=11"
  "TimeStepCheck.NativeRowsCarryTheEstimateUnlessTheCheckIsTurnedOff=10"
  "YadeLinearCohesion.ManyParticlesUseTheCollidersCandidatesAndStillMatch=10"
  "Tiers.StoredEnsemblesAreReadInTheFastTierRunAfreshInTheFullTierAndFailTheGateWhenStale=9"
  "FakeLammps.ABinaryThatHangsOnTheVersionProbeIsReportedWithinTheTimeout=5"
  "FakeLammps.AHungRunIsReportedWithinTheTimeoutAndKilled=4"
  "FakeYade.AHungRunIsReportedWithinTheTimeoutAndKilled=4")
if(DEMWB_TEST_COSTS_LIST_ONLY)  # read by cmake/CheckTestCosts.cmake
  return()
endif()
foreach(entry IN LISTS demwb_test_costs)
  string(REPLACE "=" ";" pair "${entry}")
  list(GET pair 0 name)
  list(GET pair 1 seconds)
  set_tests_properties("${name}" PROPERTIES COST ${seconds})
endforeach()
