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

#endif
