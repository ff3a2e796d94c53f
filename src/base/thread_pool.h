/* collide: the built-in task pool the 2D world uses when it is given more than one worker and no
 * task callbacks. workerCount - 1 threads are started with the pool and joined when it is
 * destroyed; the thread that finishes a task (the stepping thread) works on it too, as worker 0.
 * One task at a time: cdThreadPool_Enqueue hands the item range out in blocks, and
 * cdThreadPool_Finish works on the task until every block is done. The signatures are those of
 * cdEnqueueTaskCallback and cdFinishTaskCallback (world2.h), with the pool as userContext. */
#ifndef COLLIDE_THREAD_POOL_H
#define COLLIDE_THREAD_POOL_H

#include "collide/world2.h"

typedef struct cdThreadPool cdThreadPool;

/* NULL when out of memory, when no thread could be started or when the build has no threads
 * (WebAssembly): the caller then runs everything on its own thread. */
cdThreadPool* cdThreadPool_Create(int workerCount);
void cdThreadPool_Destroy(cdThreadPool* pool);
void* cdThreadPool_Enqueue(cdTaskCallback* task, int itemCount, int minRange, void* taskContext, void* pool);
void cdThreadPool_Finish(void* userTask, void* pool);
/* Hands each of the itemCount items to the pool's threads as a range of its own, never running
 * one on the calling thread here (cdThreadPool_Enqueue runs a task of one range inline); finish
 * it with cdThreadPool_Finish, which runs the items no thread has taken yet. */
void* cdThreadPool_EnqueueEach(cdTaskCallback* task, int itemCount, void* taskContext, cdThreadPool* pool);
/* One turn of a wait for another thread's work: spin counts the turns of this wait (0, 1, ...);
 * the first turns pause the processor briefly, the later ones give it to another thread. */
void cdThreadPool_Wait(int spin);

#if !defined(__STDC_NO_ATOMICS__)
#include <stdatomic.h>
/* A count that threads add to and wait on: the end of a stage of the step, a number of finished
 * blocks. A waiting thread pauses the processor for a short while (another thread's block takes
 * microseconds), then, where the system has them (Linux futexes), sleeps until an addition wakes
 * it, so that its processor is free: a thread descheduled in the middle of a block (its processor
 * taken by another program) can then move there and finish, instead of the whole step waiting for
 * its processor to come back. Elsewhere the wait gives its processor away turn by turn. */
typedef struct cdSyncCount
{
	atomic_int value;
	atomic_int sleepers;
} cdSyncCount;

void cdSyncCount_Init(cdSyncCount* count, int value);
/* Adds n (release: what this thread wrote before is seen by a thread whose wait it ends). */
void cdSyncCount_Add(cdSyncCount* count, int n);
/* Returns once the value is at least target (acquire). */
void cdSyncCount_AwaitAtLeast(cdSyncCount* count, int target);
#endif

#endif
